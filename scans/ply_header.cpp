#include "scans/ply_header.hpp"

#include <charconv>

#include "fspm/error.hpp"
#include "scans/text_lines.hpp"

namespace fspm::scans {
namespace {

PlyType type_from_name(std::string_view name, const std::string& path, int line) {
  struct Entry {
    std::string_view a, b;
    PlyType type;
  };
  static constexpr Entry kTypes[] = {
      {"char", "int8", PlyType::kInt8},        {"uchar", "uint8", PlyType::kUint8},
      {"short", "int16", PlyType::kInt16},     {"ushort", "uint16", PlyType::kUint16},
      {"int", "int32", PlyType::kInt32},       {"uint", "uint32", PlyType::kUint32},
      {"float", "float32", PlyType::kFloat32}, {"double", "float64", PlyType::kFloat64}};
  for (const Entry& e : kTypes) {
    if (name == e.a || name == e.b) return e.type;
  }
  throw ParseError("unknown PLY property type '" + std::string(name) +
                       "', expected char, uchar, short, ushort, int, uint, float or double",
                   path, line);
}

void add_property(PlyHeader& h, const std::vector<std::string_view>& f, const std::string& path,
                  int line) {
  if (h.elements.empty()) throw ParseError("'property' before any 'element'", path, line);
  PlyProperty p;
  if (f.size() == 5 && f[1] == "list") {
    p.is_list = true;
    p.count_type = type_from_name(f[2], path, line);
    p.type = type_from_name(f[3], path, line);
    p.name = std::string(f[4]);
  } else if (f.size() == 3) {
    p.type = type_from_name(f[1], path, line);
    p.name = std::string(f[2]);
  } else {
    throw ParseError("expected 'property TYPE NAME' or 'property list COUNT ITEM NAME'", path,
                     line);
  }
  h.elements.back().properties.push_back(p);
}

void set_format(PlyHeader& h, const std::vector<std::string_view>& f, const std::string& path,
                int line) {
  const std::string_view name = f.size() >= 2 ? f[1] : std::string_view{};
  if (name == "ascii") {
    h.format = PlyFormat::kAscii;
  } else if (name == "binary_little_endian") {
    h.format = PlyFormat::kBinaryLittleEndian;
  } else if (name == "binary_big_endian") {
    h.format = PlyFormat::kBinaryBigEndian;
  } else {
    throw ParseError("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'", path,
                     line);
  }
}

// An element with records but no properties would be read as endless empty records, and a
// second element of the same name (two "vertex" elements) would be read as one: both rejected.
void check_new_element(const PlyHeader& h, std::string_view name, const std::string& path,
                       int line) {
  for (const PlyElement& e : h.elements) {
    if (e.name == name) {
      throw ParseError("the element '" + std::string(name) + "' is declared twice", path, line);
    }
  }
}

void check_has_properties(const PlyHeader& h, const std::string& path, int line) {
  if (h.elements.empty()) return;
  const PlyElement& e = h.elements.back();
  if (e.count > 0 && e.properties.empty()) {
    throw ParseError("the element '" + e.name + "' has " + std::to_string(e.count) +
                         " records but no 'property' line",
                     path, line);
  }
}

}  // namespace

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::kInt8:
    case PlyType::kUint8:
      return 1;
    case PlyType::kInt16:
    case PlyType::kUint16:
      return 2;
    case PlyType::kInt32:
    case PlyType::kUint32:
    case PlyType::kFloat32:
      return 4;
    case PlyType::kFloat64:
      return 8;
  }
  return 0;
}

PlyHeader parse_ply_header(std::string_view data, const std::string& path) {
  TextLines lines(data);
  std::string_view line;
  if (!lines.next(line) || line != "ply")
    throw ParseError("expected 'ply' on the first line", path, 1);
  PlyHeader h;
  while (lines.next(line)) {
    const std::vector<std::string_view> f = split_fields(line);
    if (f.empty() || f[0] == "comment" || f[0] == "obj_info") continue;
    if (f[0] == "end_header") {
      check_has_properties(h, path, lines.line_number());
      h.data_offset = lines.offset();
      h.data_line = lines.line_number() + 1;
      return h;
    }
    if (f[0] == "format") {
      set_format(h, f, path, lines.line_number());
    } else if (f[0] == "element" && f.size() == 3) {
      check_has_properties(h, path, lines.line_number());
      check_new_element(h, f[1], path, lines.line_number());
      PlyElement e;
      e.name = std::string(f[1]);
      const auto r = std::from_chars(f[2].data(), f[2].data() + f[2].size(), e.count);
      if (r.ec != std::errc{} || r.ptr != f[2].data() + f[2].size()) {
        throw ParseError("expected an element count, got '" + std::string(f[2]) + "'", path,
                         lines.line_number());
      }
      h.elements.push_back(std::move(e));
    } else if (f[0] == "property") {
      add_property(h, f, path, lines.line_number());
    } else {
      throw ParseError("unknown PLY header line '" + std::string(line.substr(0, 40)) + "'", path,
                       lines.line_number());
    }
  }
  throw ParseError("the header has no 'end_header' line", path, lines.line_number());
}

}  // namespace fspm::scans
