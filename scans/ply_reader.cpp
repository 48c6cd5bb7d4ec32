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

// A value of `type` at `p`, in the machine's byte order.
double load(PlyType type, const char* p) {
  const auto as = [p]<class T>(T) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return static_cast<double>(v);
  };
  switch (type) {
    case PlyType::kInt8:
      return as(std::int8_t{});
    case PlyType::kUint8:
      return as(std::uint8_t{});
    case PlyType::kInt16:
      return as(std::int16_t{});
    case PlyType::kUint16:
      return as(std::uint16_t{});
    case PlyType::kInt32:
      return as(std::int32_t{});
    case PlyType::kUint32:
      return as(std::uint32_t{});
    case PlyType::kFloat32:
      return as(float{});
    case PlyType::kFloat64:
      return as(double{});
  }
  return 0.0;
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
    return load(type, reinterpret_cast<const char*>(b));
  }
  std::size_t offset() const { return pos_; }
  std::size_t remaining() const { return data_.size() - std::min(pos_, data_.size()); }

 private:
  std::string_view data_;
  std::size_t pos_;
  bool swap_;
  const std::string& path_;
};

bool is_face_list(const PlyElement& e, const PlyProperty& p) {
  return e.name == "face" && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index");
}

// An element of one list of 32-bit integers among scalar properties (the face element as most
// writers give it), in bulk; the list is kept when it is the face list and `faces` is given.
bool read_bulk_list(const PlyElement& e, std::string_view data, std::size_t& pos,
                    const std::string& path, std::vector<std::vector<std::uint32_t>>* faces) {
  const PlyProperty* list = nullptr;
  std::size_t before = 0, after = 0;  // bytes of the scalar properties around the list
  for (const PlyProperty& p : e.properties) {
    if (p.is_list && list != nullptr) return false;
    if (p.is_list) list = &p;
    if (!p.is_list) (list == nullptr ? before : after) += ply_type_size(p.type);
  }
  if (list == nullptr || (list->type != PlyType::kInt32 && list->type != PlyType::kUint32)) {
    return false;
  }
  const bool keep = faces != nullptr && is_face_list(e, *list);
  const std::size_t count_size = ply_type_size(list->count_type);
  std::vector<std::vector<std::uint32_t>> read;
  if (keep) read.reserve(std::min(e.count, data.size() - pos));  // a face takes a byte at least
  std::size_t at = pos;
  for (std::size_t k = 0; k < e.count; ++k) {
    if (data.size() - at < before + count_size) return false;
    at += before;
    const double n = load(list->count_type, data.data() + at);
    at += count_size;
    if (!(n >= 0.0) || static_cast<double>((data.size() - at) / 4) < n) return false;
    const auto size = static_cast<std::size_t>(n);
    if (data.size() - at - 4 * size < after) return false;
    if (keep) {
      std::vector<std::uint32_t>& face = read.emplace_back(size);
      if (size > 0) std::memcpy(face.data(), data.data() + at, 4 * size);
      if (list->type == PlyType::kInt32) {
        for (const std::uint32_t i : face) {
          if (i > 0x7fffffffu) face_index(static_cast<std::int32_t>(i), path);  // throws
        }
      }
    }
    at += 4 * size + after;
  }
  if (keep) {
    faces->insert(faces->end(), std::make_move_iterator(read.begin()),
                  std::make_move_iterator(read.end()));
  }
  pos = at;
  return true;
}

// The common layouts in the machine's byte order, read in bulk rather than value by value: an
// element of scalar properties only (fixed record size; the vertex element's x, y, z taken at
// their offsets) and an element of one list of 32-bit integers among scalars (read_bulk_list).
// Returns false, having read nothing, for another layout or a file too short, which the
// value-by-value reader then handles (and reports).
bool read_bulk(const PlyElement& e, std::string_view data, std::size_t& pos,
               const std::string& path, PointSet& out,
               std::vector<std::vector<std::uint32_t>>* faces) {
  // The header may promise data past the end (no newline after end_header, nothing after it).
  if (pos > data.size()) return false;
  const bool scalars = std::none_of(e.properties.begin(), e.properties.end(),
                                    [](const PlyProperty& p) { return p.is_list; });
  if (scalars) {
    std::size_t stride = 0;
    std::array<std::size_t, 3> at{};
    const std::array<int, 3> col = xyz_columns(e);
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      for (int c = 0; c < 3; ++c) at[c] = col[c] == static_cast<int>(i) ? stride : at[c];
      stride += ply_type_size(e.properties[i].type);
    }
    if (stride == 0 || (data.size() - pos) / stride < e.count) return false;
    const bool has_xyz = col[0] >= 0 && col[1] >= 0 && col[2] >= 0;
    if (e.name == "vertex" && !has_xyz) return false;  // (another element named vertex)
    if (e.name == "vertex") {
      out.points.reserve(e.count);
      std::array<PlyType, 3> type{};
      for (int c = 0; c < 3; ++c) type[c] = e.properties[static_cast<std::size_t>(col[c])].type;
      for (std::size_t k = 0; k < e.count; ++k) {
        const char* record = data.data() + pos + k * stride;
        const Eigen::Vector3d p(load(type[0], record + at[0]), load(type[1], record + at[1]),
                                load(type[2], record + at[2]));
        if (!p.allFinite()) {
          throw ParseError("vertex " + std::to_string(k) + " at byte " +
                               std::to_string(pos + k * stride) +
                               " has a nan or infinite coordinate",
                           path);
        }
        out.points.push_back(p);
      }
    }
    pos += e.count * stride;
    return true;
  }
  return read_bulk_list(e, data, pos, path, faces);
}

// One element value by value.
void read_element(const PlyElement& e, BinaryCursor& cur, const std::string& path, PointSet& out,
                  std::vector<std::vector<std::uint32_t>>* faces) {
  const std::array<int, 3> col = xyz_columns(e);
  const bool is_vertex = e.name == "vertex";
  // A vertex takes at least three bytes: a count the file cannot hold reserves no more.
  if (is_vertex) out.points.reserve(std::min(e.count, cur.remaining() / 3));
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

// "200000 vertex and 0 face": what the header declares, for messages about its counts.
std::string declared_counts(const PlyHeader& h) {
  std::string out;
  for (const PlyElement& e : h.elements) {
    out += (out.empty() ? "" : " and ") + std::to_string(e.count) + " " + e.name;
  }
  return out;
}

// The data of a header whose elements have fixed-size records only must be exactly as long as
// the counts say: stray bytes shift every value after them, a short file lacks some.
void check_fixed_binary_size(const PlyHeader& h, std::string_view data, const std::string& path) {
  double expected = 0.0;
  for (const PlyElement& e : h.elements) {
    std::size_t stride = 0;
    for (const PlyProperty& p : e.properties) {
      if (p.is_list) return;  // the size is known only once read
      stride += ply_type_size(p.type);
    }
    expected += static_cast<double>(e.count) * static_cast<double>(stride);
  }
  const std::size_t held = data.size() - std::min(h.data_offset, data.size());
  if (expected == static_cast<double>(held)) return;
  // Counts near 2^64 times their record size pass 2^64 bytes, where the conversion is undefined.
  const std::string bytes = expected < 0x1.0p64
                                ? std::to_string(static_cast<std::uint64_t>(expected))
                                : "more than 10^19";
  throw ParseError("the header declares " + declared_counts(h) + " (" + bytes +
                       " bytes of data), the file holds " + std::to_string(held) +
                       " bytes after its header (to byte " + std::to_string(data.size()) +
                       "): a header count that does not match the data",
                   path);
}

// Faces of the "face" element, kept only when `faces` is given.
void read_binary(const PlyHeader& h, std::string_view data, const std::string& path, PointSet& out,
                 std::vector<std::vector<std::uint32_t>>* faces) {
  const bool native =
      (h.format == PlyFormat::kBinaryBigEndian) == (std::endian::native == std::endian::big);
  check_fixed_binary_size(h, data, path);
  std::size_t pos = h.data_offset;
  for (const PlyElement& e : h.elements) {
    if (native && read_bulk(e, data, pos, path, out, faces)) continue;
    BinaryCursor cur(data, pos, h.format == PlyFormat::kBinaryBigEndian, path);
    read_element(e, cur, path, out, faces);
    pos = cur.offset();
  }
  if (pos < data.size()) {
    throw ParseError("the header declares " + declared_counts(h) + ", which end at byte " +
                         std::to_string(pos) + " of " + std::to_string(data.size()) +
                         ": a header count that does not match the data",
                     path);
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
  while (lines.next(line)) {
    ++line_no;
    if (!split_fields(line).empty()) {
      throw ParseError("more lines than the header declares (" + declared_counts(h) +
                           "): a header count that does not match the data",
                       path, line_no);
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
