#pragma once
// Wavefront OBJ meshes with groups: v lines (vertices), f lines (polygons, "i", "i/t", "i/t/n",
// "i//n", negative indices relative to the end), g and o lines start a group that the following
// faces belong to. Other statements (vt, vn, usemtl, mtllib, s, l) are skipped. Errors name the
// file and line.
#include <string>
#include <string_view>
#include <vector>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct GroupedMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<std::uint32_t>> faces;  // vertex indices, 0-based
  std::vector<std::uint32_t> face_group;          // index into group_names, one per face
  std::vector<std::string> group_names;           // "default" for faces before any g line
};

GroupedMesh read_obj_mesh(const std::string& path);
GroupedMesh parse_obj_mesh(std::string_view text, const std::string& path);

}  // namespace fspm::scans
