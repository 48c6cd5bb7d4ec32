#pragma once
// Checked access to the fields of a parsed JSON document: every failure throws ValueError naming
// the file, the line, the JSON path and what was expected ("/obstacles/1/height: expected a
// non-negative height, got -2").
#include <Eigen/Core>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

namespace fspm {

// Parses `text` as JSON (nesting depth checked); ParseError with line and column when malformed.
nlohmann::json parse_json_text(std::string_view text, const std::string& file_name);

class JsonFields {
 public:
  // `text`: the document as written, to find the line of a failing path.
  JsonFields(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  [[noreturn]] void fail(const std::string& path, const std::string& expected,
                         const nlohmann::json* got = nullptr) const;
  // Every key of `obj` must be one of `allowed`.
  void check_keys(const nlohmann::json& obj, const std::string& path,
                  std::initializer_list<const char*> allowed) const;
  // A finite number in [lo, hi]; `what` is the expectation in the message.
  double number(const nlohmann::json& obj, const std::string& path, const char* key, double lo,
                double hi, const std::string& what) const;
  std::optional<double> optional_number(const nlohmann::json& obj, const std::string& path,
                                        const char* key, double lo, double hi,
                                        const std::string& what) const;
  std::optional<bool> optional_boolean(const nlohmann::json& obj, const std::string& path,
                                       const char* key) const;
  // A non-empty string.
  std::string text(const nlohmann::json& obj, const std::string& path, const char* key,
                   const std::string& what) const;
  // An array of N numbers, each within 1e9 (coordinates beyond are surely mistakes and would
  // overflow spatial indices).
  template <int N>
  Eigen::Matrix<double, N, 1> vec(const nlohmann::json& obj, const std::string& path,
                                  const char* key) const {
    const std::string p = path + "/" + key;
    if (!obj.contains(key)) fail(p, vec_what(N) + " (missing)");
    return vec_value<N>(obj.at(key), p);
  }
  template <int N>
  Eigen::Matrix<double, N, 1> vec_value(const nlohmann::json& v, const std::string& p) const {
    if (!v.is_array() || v.size() != N) fail(p, vec_what(N), &v);
    Eigen::Matrix<double, N, 1> out;
    for (int i = 0; i < N; ++i) {
      if (!v[i].is_number() || !(std::abs(v[i].get<double>()) <= 1e9)) fail(p, vec_what(N), &v);
      out[i] = v[i].get<double>();
    }
    return out;
  }

 private:
  static std::string vec_what(int n);

  std::string_view text_;
  std::string file_;
};

}  // namespace fspm
