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

std::uint32_t face_index(double v, const std::string& path) {
  if (!(v >= 0.0) || v >= 4294967295.0 || v != std::floor(v)) {
    throw ParseError(
        "a face names the vertex index " + std::to_string(v) + ", expected a whole number from 0",
        path);
  }
  return static_cast<std::uint32_t>(v);
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

bool is_face_list(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// Faces of the "face" element, kept only when `faces` is given.
void read_binary(const PlyHeader& h, std::string_view data, const std::string& path, PointSet& out,
                 std::vector<std::vector<std::uint32_t>>* faces) {
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
          const bool keep = faces != nullptr && is_face_list(e, p);
          if (keep) faces->emplace_back();
          for (double j = 0; j < v; ++j) {
            const double index = cur.read(p.type);
            if (keep) faces->back().push_back(face_index(index, path));
          }
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

// An ASCII face line: the values of the face element's properties, the vertex list kept.
void read_ascii_face(const PlyElement& e, const std::vector<std::string_view>& f,
                     const std::string& path, int line_no,
                     std::vector<std::vector<std::uint32_t>>& faces) {
  std::size_t at = 0;
  for (const PlyProperty& p : e.properties) {
    if (at >= f.size()) throw ParseError("the face line ends early", path, line_no);
    if (!p.is_list) {
      ++at;
      continue;
    }
    const double count = parse_coordinate(f[at++], path, line_no);
    const bool keep = is_face_list(e, p);
    if (keep) faces.emplace_back();
    for (double j = 0; j < count; ++j) {
      if (at >= f.size()) throw ParseError("the face line ends inside its list", path, line_no);
      const double v = parse_coordinate(f[at++], path, line_no);
      if (keep) faces.back().push_back(face_index(v, path));
    }
  }
}

void read_ascii(const PlyHeader& h, std::string_view data, const std::string& path, PointSet& out,
                std::vector<std::vector<std::uint32_t>>* faces) {
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
      if (faces != nullptr && e.name == "face") {
        read_ascii_face(e, split_fields(line), path, line_no, *faces);
      }
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

namespace {

PointSet parse_ply(std::string_view data, const std::string& path,
                   std::vector<std::vector<std::uint32_t>>* faces) {
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
    read_ascii(h, data, path, out, faces);
  } else {
    read_binary(h, data, path, out, faces);
  }
  return out;
}

}  // namespace

PointSet parse_ply_points(std::string_view data, const std::string& path) {
  return parse_ply(data, path, nullptr);
}

GroupedMesh parse_ply_mesh(std::string_view data, const std::string& path) {
  GroupedMesh m;
  m.vertices = parse_ply(data, path, &m.faces).points;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    for (const std::uint32_t i : m.faces[f]) {
      if (i >= m.vertices.size()) {
        throw ParseError("face " + std::to_string(f) + " names vertex " + std::to_string(i) +
                             " of " + std::to_string(m.vertices.size()),
                         path);
      }
    }
  }
  m.group_names.push_back("default");
  m.face_group.assign(m.faces.size(), 0);
  return m;
}

GroupedMesh read_ply_mesh(const std::string& path) {
  return parse_ply_mesh(read_input_file(path), path);
}

PointSet read_ply_points(const std::string& path) {
  return parse_ply_points(read_input_file(path), path);
}

}  // namespace fspm::scans
