#pragma once
// Little-endian byte packing for the .clusters file, with reads that report the byte offset of
// a truncated or wrong field.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "fspm/error.hpp"

namespace fspm::scans {

class ByteWriter {
 public:
  template <class T>
  void put(T value) {
    char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));  // the supported platforms are little-endian
    out_.append(b, sizeof(T));
  }
  void put_bytes(std::string_view s) { out_.append(s); }
  std::string& bytes() { return out_; }

 private:
  std::string out_;
};

class ByteReader {
 public:
  ByteReader(std::string_view data, const std::string& path) : data_(data), path_(path) {}
  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, data_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string_view get_bytes(std::size_t n, const char* what) {
    need(n, what);
    pos_ += n;
    return data_.substr(pos_ - n, n);
  }
  std::size_t offset() const { return pos_; }
  bool at_end() const { return pos_ == data_.size(); }
  std::size_t remaining() const { return data_.size() - pos_; }
  [[noreturn]] void fail(const std::string& message, std::size_t at) const {
    throw ParseError(message + " at byte " + std::to_string(at), path_);
  }

 private:
  void need(std::size_t n, const char* what) const {
    if (pos_ + n > data_.size()) {
      fail(std::string("the file ends inside ") + what + " (" + std::to_string(data_.size()) +
               " bytes)",
           pos_);
    }
  }
  std::string_view data_;
  std::size_t pos_ = 0;
  const std::string& path_;
};

}  // namespace fspm::scans
