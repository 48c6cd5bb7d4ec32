#include "io/placed_mesh.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <limits>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/input_file.hpp"
#include "fspm/vertex_normals.hpp"
#include "scans/gltf_reader.hpp"
#include "scans/obj_reader.hpp"

namespace fspm::io {
namespace {

// Area-weighted vertex normals, for meshes that carry none.
std::vector<Eigen::Vector3f> vertex_normals(const graphics::TriangleMesh& mesh) {
  return area_weighted_vertex_normals(mesh.positions, mesh.triangles);
}

}  // namespace

graphics::TriangleMesh grouped_mesh_triangles(const scans::GroupedMesh& obj) {
  graphics::TriangleMesh mesh;
  for (const Eigen::Vector3d& v : obj.vertices) {
    mesh.positions.push_back(v.cast<float>());
    mesh.uvs.emplace_back(0.0f, 0.0f);
  }
  for (const auto& face : obj.faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      mesh.triangles.push_back({face[0], face[k], face[k + 1]});
      mesh.materials.push_back(graphics::Material::kLeaf);
    }
  }
  mesh.normals = vertex_normals(mesh);
  return mesh;
}

namespace {

// fspm's materials by the names its glTF writer gives them; any other name draws as leaf.
graphics::Material material_named(const std::string& name) {
  return graphics::find_material(name).value_or(graphics::Material::kLeaf);
}

// The vertex colours (graphics::kVertexColorAttributes) of a mesh appended at `base`; vertices
// of meshes without colours keep NaN: their material's colour.
void append_colours(const aiMesh& in, std::size_t base, graphics::TriangleMesh& out) {
  constexpr float kNone = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t c = 0; c < 3; ++c) {
    const std::string name(graphics::kVertexColorAttributes[c]);
    if (!out.has_attribute(name)) out.attributes.push_back({name, {}});
    std::vector<float>& values = out.add_attribute(name);
    values.resize(out.positions.size(), kNone);
    for (unsigned v = 0; v < in.mNumVertices; ++v) {
      const aiColor4D& colour = in.mColors[0][v];
      values[base + v] = c == 0 ? colour.r : c == 1 ? colour.g : colour.b;
    }
  }
}

void append_mesh(const aiScene& scene, const aiMesh& in, const aiMatrix4x4& to_scene,
                 graphics::TriangleMesh& out) {
  const std::size_t base = out.positions.size();
  const aiMatrix3x3 turn(to_scene);
  for (unsigned v = 0; v < in.mNumVertices; ++v) {
    const aiVector3D p = to_scene * in.mVertices[v];
    out.positions.emplace_back(p.x, p.y, p.z);
    aiVector3D n = in.HasNormals() ? turn * in.mNormals[v] : aiVector3D(0, 0, 0);
    out.normals.emplace_back(Eigen::Vector3f(n.x, n.y, n.z).normalized());
    out.uvs.emplace_back(0.0f, 0.0f);
  }
  if (in.HasVertexColors(0)) append_colours(in, base, out);
  const graphics::Material m =
      material_named(scene.mMaterials[in.mMaterialIndex]->GetName().C_Str());
  for (unsigned f = 0; f < in.mNumFaces; ++f) {
    const aiFace& face = in.mFaces[f];
    if (face.mNumIndices != 3) continue;  // a point or a line
    out.triangles.push_back({static_cast<std::uint32_t>(base + face.mIndices[0]),
                             static_cast<std::uint32_t>(base + face.mIndices[1]),
                             static_cast<std::uint32_t>(base + face.mIndices[2])});
    out.materials.push_back(m);
  }
}

void append_subtree(const aiScene& scene, const aiNode& node, const aiMatrix4x4& parent_to_scene,
                    graphics::TriangleMesh& out) {
  const aiMatrix4x4 to_scene = parent_to_scene * node.mTransformation;
  for (unsigned k = 0; k < node.mNumMeshes; ++k) {
    append_mesh(scene, *scene.mMeshes[node.mMeshes[k]], to_scene, out);
  }
  for (unsigned c = 0; c < node.mNumChildren; ++c) {
    append_subtree(scene, *node.mChildren[c], to_scene, out);
  }
}

// A glTF mesh through assimp, node transforms applied, with its vertex colours and fspm's
// material names (the format fspm crown and fspm mesh write).
graphics::TriangleMesh read_gltf_triangles(const std::string& path) {
  scans::check_gltf_input(path);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw ParseError(std::string("cannot read as glTF 2.0: ") + importer.GetErrorString(), path);
  }
  graphics::TriangleMesh mesh;
  append_subtree(*scene, *scene->mRootNode, aiMatrix4x4(), mesh);
  for (auto& a : mesh.attributes) {
    const bool colour = graphics::is_vertex_color_attribute(a.name);
    a.values.resize(mesh.positions.size(), colour ? std::numeric_limits<float>::quiet_NaN() : 0.0f);
  }
  if (mesh.triangles.empty()) throw ParseError("no triangle in the glTF meshes", path);
  // A vertex without a normal in the file gets the normal of its triangles.
  const auto normals = vertex_normals(mesh);
  for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
    if (!mesh.normals[v].allFinite() || mesh.normals[v].norm() < 0.5f) mesh.normals[v] = normals[v];
  }
  return mesh;
}

}  // namespace

bool is_placed_mesh_path(const std::string& path) {
  return is_grouped_mesh_kind(file_kind_by_extension(path));
}

graphics::TriangleMesh read_placed_mesh(const std::string& path) {
  const FileKind kind = file_kind(path);
  if (kind == FileKind::kGlb || kind == FileKind::kGltf) return read_gltf_triangles(path);
  if (kind == FileKind::kObj) {
    const scans::GroupedMesh obj = scans::read_obj_mesh(path);
    graphics::TriangleMesh mesh = grouped_mesh_triangles(obj);
    if (mesh.triangles.empty()) {
      throw ParseError("no triangle in the OBJ file (" + std::to_string(obj.vertices.size()) +
                           " vertices, no face of 3 or more)",
                       path);
    }
    return mesh;
  }
  throw ValueError("expected a .glb, .gltf or .obj mesh", path);
}

}  // namespace fspm::io
