#pragma once
// Polygon meshes from files, by extension: Wavefront .obj (with its groups) and .ply (ASCII or
// binary, faces as vertex-index lists), the formats `fspm mesh` writes that carry faces.
#include <string>
#include <string_view>

#include "scans/obj_reader.hpp"

namespace fspm::scans {

// True for the extensions read_mesh_file reads (.obj, .ply, any case).
bool is_mesh_file(std::string_view path);

// Throws ValueError for another extension, ParseError for a malformed file.
GroupedMesh read_mesh_file(const std::string& path);

}  // namespace fspm::scans
