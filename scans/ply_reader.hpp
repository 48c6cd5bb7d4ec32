#pragma once
// PLY point sets (Turk's polygon file format): ASCII, binary little- and big-endian. The x, y, z
// properties of the "vertex" element are read (any scalar type); other properties and elements
// (normals, colours; faces, except by read_ply_mesh) are skipped. Errors name the file and the
// header line, the data line (ASCII) or the byte offset (binary).
#include <string>
#include <string_view>

#include "scans/obj_reader.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

PointSet read_ply_points(const std::string& path);
// The same from text already in memory; `path` only names it in errors.
PointSet parse_ply_points(std::string_view data, const std::string& path);

// A PLY mesh: the vertices and the vertex lists ("vertex_indices" or "vertex_index") of the
// "face" element, as one group. Throws ParseError for a face naming a vertex that does not exist.
GroupedMesh read_ply_mesh(const std::string& path);
GroupedMesh parse_ply_mesh(std::string_view data, const std::string& path);

}  // namespace fspm::scans
