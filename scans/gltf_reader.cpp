#include "scans/gltf_reader.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
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

// The colours of `mesh` appended at `first`; vertices before them without colours get NaN.
void append_colours(const aiMesh& mesh, std::size_t first, GltfMesh& m) {
  constexpr float kNone = std::numeric_limits<float>::quiet_NaN();
  m.colours.resize(first, Eigen::Vector3f::Constant(kNone));
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiColor4D& c = mesh.mColors[0][v];
    m.colours.emplace_back(c.r, c.g, c.b);
  }
}

void append_vertices(const aiMesh& mesh, const aiMatrix4x4& to_scene, GltfMesh& m) {
  const aiMatrix3x3 turn(to_scene);
  const std::size_t first = m.mesh.vertices.size();
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D p = to_scene * mesh.mVertices[v];
    m.mesh.vertices.emplace_back(p.x, p.y, p.z);
    const aiVector3D n = mesh.HasNormals() ? turn * mesh.mNormals[v] : aiVector3D(0, 0, 0);
    m.normals.push_back(Eigen::Vector3f(n.x, n.y, n.z).normalized());
  }
  if (mesh.HasVertexColors(0)) append_colours(mesh, first, m);
}

void append_node_mesh(const aiScene& scene, const aiNode& node, const aiMatrix4x4& to_scene,
                      GltfMesh& m) {
  const auto group = static_cast<std::uint32_t>(m.mesh.group_names.size());
  m.mesh.group_names.push_back(group_name(scene, node));
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[k]];
    const auto first = static_cast<std::uint32_t>(m.mesh.vertices.size());
    append_vertices(mesh, to_scene, m);
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // a point or a line
      m.mesh.faces.push_back(
          {first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
      m.mesh.face_group.push_back(group);
      m.face_material.push_back(mesh.mMaterialIndex);
    }
  }
}

// Depth first, children in the file's order, so groups keep the order of the file's nodes.
void append_subtree(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_to_scene,
                    GltfMesh& m) {
  const aiMatrix4x4 to_scene = parent_to_scene * node.mTransformation;
  if (node.mNumMeshes > 0) append_node_mesh(scene, node, to_scene, m);
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    append_subtree(scene, *node.mChildren[c], to_scene, m);
  }
}

// The chunks after the GLB header (glTF 2.0 spec, "Chunks"): each an 8-byte header (length, type)
// and its data, the first of type JSON, together exactly the rest of the file. The decoder
// allocates a chunk from its declared length before reading it: a length past the end of the
// file (4 GB from 4 bytes) is refused here, where only the chunk headers are read.
void check_glb_chunks(std::ifstream& in, const std::string& path, std::uint64_t file_bytes) {
  constexpr std::uint32_t kJson = 0x4E4F534A;  // "JSON", little-endian
  std::uint64_t at = 12;
  for (int chunk = 0; at < file_bytes; ++chunk) {
    unsigned char h[8] = {};
    in.seekg(static_cast<std::streamoff>(at));
    if (file_bytes - at < 8 || !in.read(reinterpret_cast<char*>(h), sizeof h)) {
      throw ParseError("GLB chunk " + std::to_string(chunk) + " at byte " + std::to_string(at) +
                           ": its 8-byte header is cut off by the end of the file",
                       path);
    }
    const std::uint64_t length = std::uint64_t{h[0]} | std::uint64_t{h[1]} << 8 |
                                 std::uint64_t{h[2]} << 16 | std::uint64_t{h[3]} << 24;
    const std::uint32_t type = std::uint32_t{h[4]} | std::uint32_t{h[5]} << 8 |
                               std::uint32_t{h[6]} << 16 | std::uint32_t{h[7]} << 24;
    if (chunk == 0 && type != kJson) {
      throw ParseError("the first GLB chunk is not JSON, expected the glTF's JSON first", path);
    }
    if (length > file_bytes - at - 8) {
      throw ParseError("GLB chunk " + std::to_string(chunk) + " declares " +
                           std::to_string(length) + " bytes, but only " +
                           std::to_string(file_bytes - at - 8) + " follow its header",
                       path);
    }
    at += 8 + length;
  }
  if (at == 12) throw ParseError("a GLB file without chunks, expected its JSON chunk", path);
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
  check_glb_chunks(in, path, file_bytes);
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

GltfMesh read_gltf(const std::string& path) {
  check_gltf_input(path);
  Assimp::Importer importer;
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw ParseError(std::string("cannot read as glTF 2.0: ") + importer.GetErrorString(), path);
  }
  GltfMesh m;
  for (unsigned i = 0; i < scene->mNumMaterials; ++i) {
    m.material_names.emplace_back(scene->mMaterials[i]->GetName().C_Str());
  }
  append_subtree(*scene, *scene->mRootNode, aiMatrix4x4(), m);
  if (m.mesh.faces.empty()) throw ParseError("no triangle in the glTF meshes", path);
  if (!m.colours.empty()) {
    m.colours.resize(m.mesh.vertices.size(),
                     Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()));
  }
  return m;
}

GroupedMesh read_gltf_mesh(const std::string& path) { return read_gltf(path).mesh; }

}  // namespace fspm::scans
