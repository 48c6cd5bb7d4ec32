#include "graphics/triangle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fspm/error.hpp"
#include "fspm/name_table.hpp"

namespace fspm::graphics {

namespace {

constexpr NameTable<Material, 6> kMaterialNames{
    "material",
    {{Material::kBark, "bark", "branches and trunk"},
     {Material::kLeaf, "leaf", "leaves"},
     {Material::kObstacle, "obstacle", "opaque obstacles"},
     {Material::kCrown, "crown", "leaf-cluster volumes"},
     {Material::kTranslucentObstacle, "translucent_obstacle", "obstacles letting light through"},
     {Material::kTerrain, "terrain", "the ground"}}};
static_assert(kMaterialNames.values() == kMaterials, "every material has its name");

}  // namespace

std::string_view material_name(Material material) { return kMaterialNames.name(material); }

std::optional<Material> find_material(std::string_view name) { return kMaterialNames.find(name); }

Material material_from_name(std::string_view name) { return kMaterialNames.from_name(name); }

std::array<float, 3> material_color(Material material) {
  switch (material) {
    case Material::kLeaf:
      return {0.25f, 0.55f, 0.15f};
    case Material::kObstacle:
      return {0.62f, 0.61f, 0.58f};
    case Material::kCrown:
      return {0.35f, 0.62f, 0.25f};
    case Material::kTranslucentObstacle:
      return {0.80f, 0.80f, 0.77f};
    case Material::kTerrain:
      return {0.52f, 0.50f, 0.34f};
    case Material::kBark:
      break;
  }
  return {0.45f, 0.32f, 0.20f};
}

Material material_from_index(int index) {
  if (index == static_cast<int>(Material::kLeaf)) return Material::kLeaf;
  if (index == static_cast<int>(Material::kObstacle)) return Material::kObstacle;
  if (index == static_cast<int>(Material::kCrown)) return Material::kCrown;
  if (index == static_cast<int>(Material::kTranslucentObstacle)) {
    return Material::kTranslucentObstacle;
  }
  if (index == static_cast<int>(Material::kTerrain)) return Material::kTerrain;
  return Material::kBark;
}

double TriangleMesh::bytes_for(std::size_t vertices, std::size_t triangles,
                               std::size_t attributes) {
  const double per_vertex = sizeof(Eigen::Vector3f) * 2 + sizeof(Eigen::Vector2f) +
                            sizeof(float) * static_cast<double>(attributes);
  const double per_triangle = sizeof(Triangle) + sizeof(Material);
  return static_cast<double>(vertices) * per_vertex + static_cast<double>(triangles) * per_triangle;
}

std::vector<float>& TriangleMesh::add_attribute(const std::string& name) {
  for (auto& a : attributes) {
    if (a.name == name) return a.values;
  }
  attributes.push_back({name, std::vector<float>(positions.size(), 0.0f)});
  return attributes.back().values;
}

bool TriangleMesh::has_attribute(std::string_view name) const {
  return std::any_of(attributes.begin(), attributes.end(),
                     [&](const VertexAttribute& a) { return a.name == name; });
}

std::span<const float> TriangleMesh::attribute(std::string_view name) const {
  for (const auto& a : attributes) {
    if (a.name == name) return a.values;
  }
  std::string known;
  for (const auto& a : attributes) known += (known.empty() ? "" : ", ") + a.name;
  throw ValueError("unknown mesh attribute '" + std::string(name) +
                   "' (expected one of: " + (known.empty() ? std::string("none") : known) + ")");
}

std::vector<std::string> TriangleMesh::attribute_names() const {
  std::vector<std::string> names;
  names.reserve(attributes.size());
  for (const auto& a : attributes) names.push_back(a.name);
  return names;
}

std::size_t TriangleMesh::triangle_count(Material material) const {
  return static_cast<std::size_t>(std::count(materials.begin(), materials.end(), material));
}

bool is_vertex_color_attribute(std::string_view name) {
  return std::find(kVertexColorAttributes.begin(), kVertexColorAttributes.end(), name) !=
         kVertexColorAttributes.end();
}

bool TriangleMesh::has_vertex_colors() const {
  return std::all_of(kVertexColorAttributes.begin(), kVertexColorAttributes.end(),
                     [this](std::string_view name) { return has_attribute(name); });
}

std::vector<std::array<float, 3>> resolved_vertex_colors(const TriangleMesh& mesh) {
  std::vector<std::array<float, 3>> out(mesh.vertex_count(), material_color(Material::kBark));
  std::vector<std::uint8_t> own(mesh.vertex_count(), 0);
  if (mesh.has_vertex_colors()) {
    const auto r = mesh.attribute("red"), g = mesh.attribute("green"), b = mesh.attribute("blue");
    for (std::size_t v = 0; v < out.size(); ++v) {
      if (std::isnan(r[v]) || std::isnan(g[v]) || std::isnan(b[v])) continue;
      out[v] = {r[v], g[v], b[v]};
      own[v] = 1;
    }
  }
  for (std::size_t t = mesh.triangle_count(); t-- > 0;) {  // the first triangle writes last
    for (const std::uint32_t v : mesh.triangles[t]) {
      if (!own[v]) out[v] = material_color(mesh.materials[t]);
    }
  }
  return out;
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto offset = static_cast<std::uint32_t>(positions.size());
  const std::size_t old_vertices = positions.size();
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  uvs.insert(uvs.end(), other.uvs.begin(), other.uvs.end());
  triangles.reserve(triangles.size() + other.triangles.size());
  for (const Triangle& t : other.triangles) {
    triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
  materials.insert(materials.end(), other.materials.begin(), other.materials.end());
  const auto missing = [](const std::string& name) {
    return is_vertex_color_attribute(name) ? std::numeric_limits<float>::quiet_NaN() : 0.0f;
  };
  for (const auto& a : other.attributes) {
    if (!has_attribute(a.name)) {
      attributes.push_back({a.name, std::vector<float>(old_vertices, missing(a.name))});
    }
  }
  for (auto& a : attributes) {
    a.values.resize(old_vertices, missing(a.name));
    bool found = false;
    for (const auto& b : other.attributes) {
      if (b.name == a.name) {
        a.values.insert(a.values.end(), b.values.begin(), b.values.end());
        found = true;
        break;
      }
    }
    if (!found) a.values.resize(positions.size(), missing(a.name));
  }
}

Eigen::Vector3f TriangleMesh::bbox_min() const {
  if (positions.empty()) return Eigen::Vector3f::Zero();
  Eigen::Vector3f lo = positions.front();
  for (const auto& p : positions) lo = lo.cwiseMin(p);
  return lo;
}

Eigen::Vector3f TriangleMesh::bbox_max() const {
  if (positions.empty()) return Eigen::Vector3f::Zero();
  Eigen::Vector3f hi = positions.front();
  for (const auto& p : positions) hi = hi.cwiseMax(p);
  return hi;
}

}  // namespace fspm::graphics
