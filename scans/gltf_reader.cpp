#include "scans/gltf_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
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

// The 12-byte header of a binary glTF (glTF 2.0 spec, "GLB File Format Specification"): magic
// "glTF", version 2, and the total length, which must be the file's size (a lying length would
// have the decoder read past the data or ignore part of it).
void check_glb_header(const std::string& path, std::uint64_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  unsigned char h[12] = {};
  if (!in.read(reinterpret_cast<char*>(h), sizeof h)) {
    throw ParseError(
        "a GLB file of " + std::to_string(file_bytes) + " bytes, shorter than its 12-byte header",
        path);
  }
  const auto u32 = [&](int at) {
    return std::uint32_t{h[at]} | std::uint32_t{h[at + 1]} << 8 | std::uint32_t{h[at + 2]} << 16 |
           std::uint32_t{h[at + 3]} << 24;
  };
  if (std::memcmp(h, "glTF", 4) != 0) {
    throw ParseError("not a GLB file (it does not start with 'glTF')", path);
  }
  if (u32(8) != file_bytes) {
    throw ParseError("the GLB header gives a length of " + std::to_string(u32(8)) +
                         " bytes, the file has " + std::to_string(file_bytes),
                     path);
  }
}

}  // namespace

// glTF is read from disk by its decoder, which opens the file again (and a .gltf its buffers
// beside it): a pipe would be consumed by the first open and block the second forever. Checked
// before anything opens it: opening a pipe blocks until a writer comes.
void check_gltf_input(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status)) {
    throw IoError("not a regular file (a pipe or device), expected a glTF file on disk", path);
  }
  open_input_file(path).reset();  // IoError for a missing, unreadable or implausibly large file
  if (file_kind_by_extension(path) == FileKind::kGlb)
    check_glb_header(path, std::filesystem::file_size(path));
}

GroupedMesh read_gltf_mesh(const std::string& path) {
  check_gltf_input(path);
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
