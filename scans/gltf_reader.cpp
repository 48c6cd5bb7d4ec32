#include "scans/gltf_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <regex>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"

namespace fspm::scans {
namespace {

// assimp names a node without a name "nodes[i]" and the meshes of a glTF mesh with several
// primitives "name-k".
std::string group_name(const aiScene& scene, const aiNode& node) {
  static const std::regex kUnnamedNode(R"(nodes\[\d+\])");
  static const std::regex kPrimitiveSuffix(R"(-\d+$)");
  const std::string name = node.mName.C_Str();
  if (!std::regex_match(name, kUnnamedNode)) return name;
  const std::string mesh = scene.mMeshes[node.mMeshes[0]]->mName.C_Str();
  if (mesh.empty()) return name;
  return node.mNumMeshes > 1 ? std::regex_replace(mesh, kPrimitiveSuffix, "") : mesh;
}

void append_node_mesh(const aiScene& scene, const aiNode& node, const aiMatrix4x4& to_scene,
                      GroupedMesh& m) {
  const auto group = static_cast<std::uint32_t>(m.group_names.size());
  m.group_names.push_back(group_name(scene, node));
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const auto first = static_cast<std::uint32_t>(m.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
      const aiVector3D p = to_scene * mesh.mVertices[v];
      m.vertices.emplace_back(p.x, p.y, p.z);
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or a line
      m.faces.push_back(
          {first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
      m.face_group.push_back(group);
    }
  }
}

// Depth first, children in the file's order, so groups keep the order of the file's nodes.
void append_subtree(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_to_scene,
                    GroupedMesh& m) {
  const aiMatrix4x4 to_scene = parent_to_scene * node.mTransformation;
  if (node.mNumMeshes > 0) append_node_mesh(scene, node, to_scene, m);
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    append_subtree(scene, *node.mChildren[c], to_scene, m);
  }
}

}  // namespace

GroupedMesh read_gltf_mesh(const std::string& path) {
  open_input_file(path);  // IoError for a missing, unreadable or implausibly large file
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw ParseError(std::string("cannot read as glTF 2.0: ") + importer.GetErrorString(), path);
  }
  GroupedMesh m;
  append_subtree(*scene, *scene->mRootNode, aiMatrix4x4(), m);
  if (m.faces.empty()) throw ParseError("no triangle in the glTF meshes", path);
  return m;
}

}  // namespace fspm::scans
