#include "io/placed_mesh.hpp"

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
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

// The vertex colours (graphics::kVertexColorAttributes); NaN draws a vertex in its material's
// colour.
void add_colours(const std::vector<Eigen::Vector3f>& colours, graphics::TriangleMesh& mesh) {
  if (colours.empty()) return;
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<float>& values =
        mesh.add_attribute(std::string(graphics::kVertexColorAttributes[c]));
    values.resize(colours.size());
    for (std::size_t v = 0; v < colours.size(); ++v) values[v] = colours[v][static_cast<int>(c)];
  }
}

// A glTF mesh read by scans/gltf_reader.hpp, with its vertex colours and fspm's material names
// (the format fspm crown and fspm mesh write).
graphics::TriangleMesh read_gltf_triangles(const std::string& path) {
  const scans::GltfMesh gltf = scans::read_gltf(path);
  graphics::TriangleMesh mesh;
  for (const Eigen::Vector3d& v : gltf.mesh.vertices) {
    mesh.positions.push_back(v.cast<float>());
    mesh.uvs.emplace_back(0.0f, 0.0f);
  }
  std::vector<graphics::Material> materials;
  for (const std::string& name : gltf.material_names) materials.push_back(material_named(name));
  for (std::size_t f = 0; f < gltf.mesh.faces.size(); ++f) {
    const auto& face = gltf.mesh.faces[f];
    mesh.triangles.push_back({face[0], face[1], face[2]});
    const std::uint32_t m = gltf.face_material[f];
    mesh.materials.push_back(m < materials.size() ? materials[m] : graphics::Material::kLeaf);
  }
  add_colours(gltf.colours, mesh);
  // A vertex without a normal in the file gets the normal of its triangles.
  mesh.normals = gltf.normals;
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
