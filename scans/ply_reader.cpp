#include "scans/ply_reader.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "scans/ply_header.hpp"
#include "scans/text_lines.hpp"

namespace fspm::scans {
namespace {

// Where x, y, z sit among an element's properties (-1: absent).
std::array<int, 3> xyz_columns(const PlyElement& e) {
  std::array<int, 3> col{-1, -1, -1};
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const std::string& n = e.properties[i].name;
    if (e.properties[i].is_list) continue;
    if (n == "x") col[0] = static_cast<int>(i);
    if (n == "y") col[1] = static_cast<int>(i);
    if (n == "z") col[2] = static_cast<int>(i);
  }
  return col;
}

class BinaryCursor {
 public:
  BinaryCursor(std::string_view data, std::size_t pos, bool big_endian, const std::string& path)
      : data_(data),
        pos_(pos),
        swap_(big_endian != (std::endian::native == std::endian::big)),
        path_(path) {}

  double read(PlyType type) {
    const std::size_t n = ply_type_size(type);
    if (pos_ + n > data_.size()) {
      throw ParseError("the file ends inside the binary data at byte " + std::to_string(pos_) +
                           " (" + std::to_string(data_.size()) + " bytes), expected more values",
                       path_);
    }
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    if (swap_) std::reverse(b, b + n);
    pos_ += n;
    return decode(type, b);
  }
  std::size_t offset() const { return pos_; }

 private:
  static double decode(PlyType type, const unsigned char* b) {
    switch (type) {
      case PlyType::kInt8:
        return static_cast<std::int8_t>(b[0]);
      case PlyType::kUint8:
        return b[0];
      case PlyType::kInt16:
        return as<std::int16_t>(b);
      case PlyType::kUint16:
        return as<std::uint16_t>(b);
      case PlyType::kInt32:
        return as<std::int32_t>(b);
      case PlyType::kUint32:
        return as<std::uint32_t>(b);
      case PlyType::kFloat32:
        return as<float>(b);
      case PlyType::kFloat64:
        return as<double>(b);
    }
    return 0.0;
  }
  template <class T>
  static double as(const unsigned char* b) {
    T v;
    std::memcpy(&v, b, sizeof v);
    return static_cast<double>(v);
  }
  std::string_view data_;
  std::size_t pos_;
  bool swap_;
  const std::string& path_;
};

void read_binary(const PlyHeader& h, std::string_view data, const std::string& path,
                 PointSet& out) {
  BinaryCursor cur(data, h.data_offset, h.format == PlyFormat::kBinaryBigEndian, path);
  for (const PlyElement& e : h.elements) {
    const std::array<int, 3> col = xyz_columns(e);
    const bool is_vertex = e.name == "vertex";
    if (is_vertex) out.points.reserve(e.count);
    for (std::size_t k = 0; k < e.count; ++k) {
      const std::size_t at = cur.offset();
      double xyz[3] = {0, 0, 0};
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const PlyProperty& p = e.properties[i];
        const double v = cur.read(p.is_list ? p.count_type : p.type);
        if (p.is_list) {
          for (double j = 0; j < v; ++j) cur.read(p.type);
        }
        for (int c = 0; c < 3; ++c) xyz[c] = col[c] == static_cast<int>(i) ? v : xyz[c];
      }
      if (!is_vertex) continue;
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
        throw ParseError("vertex " + std::to_string(k) + " at byte " + std::to_string(at) +
                             " has a nan or infinite coordinate",
                         path);
      }
      out.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
}

void read_ascii(const PlyHeader& h, std::string_view data, const std::string& path, PointSet& out) {
  TextLines lines(data, h.data_offset);
  int line_no = h.data_line - 1;
  std::string_view line;
  for (const PlyElement& e : h.elements) {
    const std::array<int, 3> col = xyz_columns(e);
    for (std::size_t k = 0; k < e.count; ++k) {
      if (!lines.next(line)) {
        throw ParseError("the file ends after " + std::to_string(k) + " of " +
                             std::to_string(e.count) + " '" + e.name + "' lines",
                         path, line_no + 1);
      }
      ++line_no;
      if (e.name != "vertex") continue;
      const std::vector<std::string_view> f = split_fields(line);
      double xyz[3];
      for (int c = 0; c < 3; ++c) {
        if (static_cast<std::size_t>(col[c]) >= f.size()) {
          throw ParseError("expected " + std::to_string(e.properties.size()) + " values", path,
                           line_no);
        }
        xyz[c] = parse_coordinate(f[static_cast<std::size_t>(col[c])], path, line_no);
      }
      out.points.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
}

}  // namespace

PointSet parse_ply_points(std::string_view data, const std::string& path) {
  const PlyHeader h = parse_ply_header(data, path);
  const PlyElement* vertex = nullptr;
  for (const PlyElement& e : h.elements) vertex = e.name == "vertex" ? &e : vertex;
  if (vertex == nullptr) throw ParseError("no 'element vertex' in the header", path);
  const std::array<int, 3> col = xyz_columns(*vertex);
  if (col[0] < 0 || col[1] < 0 || col[2] < 0) {
    throw ParseError("the vertex element lacks one of the properties x, y, z", path);
  }
  PointSet out;
  if (h.format == PlyFormat::kAscii) {
    read_ascii(h, data, path, out);
  } else {
    read_binary(h, data, path, out);
  }
  return out;
}

PointSet read_ply_points(const std::string& path) {
  return parse_ply_points(read_input_file(path), path);
}

}  // namespace fspm::scans
