#pragma once
// Meshes placed in scenes as they are: crowns reconstructed from a photograph (`fspm crown`,
// Argudo ch. 4-5), read from the .glb, .gltf or .obj the command wrote.
#include <string>

#include "graphics/triangle_mesh.hpp"
#include "scans/obj_reader.hpp"

namespace fspm::io {

// True for .glb, .gltf and .obj (any case).
bool is_placed_mesh_path(const std::string& path);

// A glTF mesh (scans/gltf_reader.hpp) with its materials and vertex colours; an .obj with every
// polygon as a fan of leaf triangles (the reader keeps groups, not materials). Throws IoError,
// ParseError or ValueError naming the file.
graphics::TriangleMesh read_placed_mesh(const std::string& path);

// Every polygon of a mesh read by scans/mesh_file.hpp as a fan of leaf triangles (the readers
// keep groups, not materials), with area-weighted vertex normals.
graphics::TriangleMesh grouped_mesh_triangles(const scans::GroupedMesh& obj);

}  // namespace fspm::io
