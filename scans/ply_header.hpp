#pragma once
// The header of a PLY file: format, elements, and their properties.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fspm::scans {

enum class PlyFormat { kAscii, kBinaryLittleEndian, kBinaryBigEndian };
enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;  // list properties only
};

struct PlyElement {
  std::string name;
  std::size_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyFormat format = PlyFormat::kAscii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;  // first byte after "end_header\n"
  int data_line = 0;            // line number of the first data line (ASCII)
};

std::size_t ply_type_size(PlyType type);
// Throws ParseError naming `path` and the header line.
PlyHeader parse_ply_header(std::string_view data, const std::string& path);

}  // namespace fspm::scans
