#pragma once
// glTF 2.0 meshes (.gltf with its buffers, .glb) read through assimp: the triangles of every mesh
// of every node in the default scene, moved to the scene's frame by the node's transform chained
// with its ancestors' (glTF 2.0 sec. 3.5.3: matrix, or translation * rotation * scale). Each node
// with a mesh is one group, named after the node, or after its mesh when the node has no name, in
// the scene's depth-first node order: a model exported with one mesh per branch keeps its branches
// as OBJ groups do. Points and lines are skipped. Coordinates are kept as stored (metres; no
// y-up to z-up turn, fspm's own .glb files are z up).
#include <string>

#include "scans/obj_reader.hpp"

namespace fspm::scans {

// Throws IoError when the file cannot be opened, ParseError (naming the file) when it is not a
// valid glTF or holds no triangle.
GroupedMesh read_gltf_mesh(const std::string& path);

}  // namespace fspm::scans
