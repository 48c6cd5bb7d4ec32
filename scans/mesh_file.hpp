#pragma once
// Polygon meshes from files, by extension: the one entry point of the mesh readers. Wavefront .obj
// (with its groups), .ply (ASCII or binary, faces as vertex-index lists; one group) and glTF 2.0
// .gltf and .glb (triangles; a group per node, scans/gltf_reader.hpp).
#include <string>
#include <string_view>

#include "scans/obj_reader.hpp"

namespace fspm::scans {

// True for the extensions read_mesh_file reads (.obj, .ply, .gltf, .glb, any case).
bool is_mesh_file(std::string_view path);

// True for the extensions whose meshes carry groups (.obj, .gltf, .glb, any case).
bool is_grouped_mesh_file(std::string_view path);

// Throws ValueError for another extension, IoError for a file that cannot be read, ParseError for
// a malformed file; every error names the file.
// `format` ("obj", "ply", "gltf" or "glb"), when given, is used instead of the extension.
GroupedMesh read_mesh_file(const std::string& path, std::string_view format = {});

}  // namespace fspm::scans
