#pragma once
// Reading a point set by file extension: .ply, .xyz/.txt/.csv, .pcd, .las (scans/las_reader.hpp;
// .laz is refused with a message to decompress it), and the meshes .obj, .gltf and .glb (their
// vertices, scans/mesh_file.hpp). Throws ValueError for another extension.
#include <string>

#include "scans/point_set.hpp"

namespace fspm::scans {

PointSet read_point_set(const std::string& path);

}  // namespace fspm::scans
