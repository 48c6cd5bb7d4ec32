#pragma once
// PLY point sets (Turk's polygon file format): ASCII, binary little- and big-endian. The x, y, z
// properties of the "vertex" element are read (any scalar type); other properties and elements
// (faces, normals, colours) are skipped. Errors name the file and the header line, the data line
// (ASCII) or the byte offset (binary).
#include <string>
#include <string_view>

#include "scans/point_set.hpp"

namespace fspm::scans {

PointSet read_ply_points(const std::string& path);
// The same from text already in memory; `path` only names it in errors.
PointSet parse_ply_points(std::string_view data, const std::string& path);

}  // namespace fspm::scans
