#pragma once
// glTF 2.0 meshes (.gltf with its buffers, .glb) read through assimp: the triangles of every mesh
// of every node in the default scene, moved to the scene's frame by the node's transform chained
// with its ancestors' (glTF 2.0 sec. 3.5.3: matrix, or translation * rotation * scale). Each node
// with a mesh is one group, named after the node, or after its mesh when the node has no name, in
// the scene's depth-first node order: a model exported with one mesh per branch keeps its branches
// as OBJ groups do. Points and lines are skipped. Coordinates are kept as stored (metres; no
// y-up to z-up turn, fspm's own .glb files are z up). This is fspm's one glTF reader: the scans
// read its groups, the scenes' crowns (io/placed_mesh.hpp) its materials, normals and colours.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "scans/obj_reader.hpp"

namespace fspm::scans {

// Everything fspm reads from a glTF file, one entry per vertex or face of `mesh`.
struct GltfMesh {
  GroupedMesh mesh;  // triangles, a group per node
  // The names of the file's materials (fspm's writer names them after graphics::Material), and
  // the material of each face.
  std::vector<std::string> material_names;
  std::vector<std::uint32_t> face_material;
  // Each vertex's normal turned with its node; zero where the file gives none.
  std::vector<Eigen::Vector3f> normals;
  // Each vertex's colour (COLOR_0, linear RGB), NaN for the vertices of meshes without colours;
  // empty when no mesh has colours.
  std::vector<Eigen::Vector3f> colours;
};

// Throws IoError when the file cannot be opened, ParseError (naming the file) when it is not a
// valid glTF or holds no triangle.
GltfMesh read_gltf(const std::string& path);
// The triangles and groups of read_gltf.
GroupedMesh read_gltf_mesh(const std::string& path);

// The checks read_gltf_mesh makes before its decoder opens the file, for other readers of glTF:
// IoError "not a regular file" for a pipe or device (the decoder reopens the file, which would
// block on a pipe), IoError for a missing or unreadable file, ParseError when a .glb's header
// does not give the file's length.
void check_gltf_input(const std::string& path);

}  // namespace fspm::scans
