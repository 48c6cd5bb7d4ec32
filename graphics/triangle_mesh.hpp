#pragma once
// TriangleMesh: the indexed triangle soup every exporter and renderer consumes. Positions,
// normals and texture coordinates are per vertex; named float attributes (age, order, light,
// pruned, ...) are per vertex too so colouring survives interpolation in any viewer. Each
// triangle carries a material (bark, leaf, crown: the translucent volume of a leaf cluster,
// obstacle: walls and boxes of a scene, or translucent obstacle: those letting light through) so
// OBJ/MTL and glTF can split them.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fspm::graphics {

enum class Material : std::uint8_t {
  kBark = 0,
  kLeaf = 1,
  kObstacle = 2,
  kCrown = 3,
  kTranslucentObstacle = 4,
  kTerrain = 5
};

inline constexpr std::array<Material, 6> kMaterials = {Material::kBark,
                                                       Material::kLeaf,
                                                       Material::kObstacle,
                                                       Material::kCrown,
                                                       Material::kTranslucentObstacle,
                                                       Material::kTerrain};

// Opacity of the crown material (leaf-cluster volumes seen through) and of translucent obstacles
// (any translucency above 0: hedges, nets, leaf clusters of a scene); the others are opaque.
inline constexpr float kCrownOpacity = 0.35f;
inline constexpr float kTranslucentObstacleOpacity = 0.4f;

// Opacity of a translucent obstacle drawn from its translucency gamma (the vertex attribute
// "translucency", Pirk eq. 4.4's gamma for obstacles): 1 - gamma, kept within [0.15, 0.9] so that
// an obstacle letting almost all light through still shows and one letting a little through
// still reads as see-through. Without the attribute, kTranslucentObstacleOpacity.
inline float translucent_obstacle_opacity(float translucency) {
  const float opacity = 1.0f - translucency;
  return opacity < 0.15f ? 0.15f : (opacity > 0.9f ? 0.9f : opacity);
}

// True for both obstacle materials.
inline bool is_obstacle(Material m) {
  return m == Material::kObstacle || m == Material::kTranslucentObstacle;
}

// "bark", "leaf", "obstacle", "crown", "translucent_obstacle", "terrain".
std::string_view material_name(Material material);
// Inverse of material_name: the material of that name, or none.
std::optional<Material> find_material(std::string_view name);
// The same, throwing ValueError listing every name when there is none.
Material material_from_name(std::string_view name);

// The material's diffuse colour, linear RGB in [0, 1], shared by every renderer and exporter:
// brown bark, green leaves, neutral grey stone for obstacles, a lighter green for crowns, a
// lighter grey for translucent obstacles, an olive brown for terrain.
std::array<float, 3> material_color(Material material);

// Material from the byte stored in PLY and VTP files; unknown values are bark.
Material material_from_index(int index);

// Vertex colours (a crown reconstructed from a photograph, fspm crown): the attributes "red",
// "green" and "blue", linear RGB in [0, 1]; NaN where a vertex has none (TriangleMesh::append
// leaves NaN on the vertices of meshes without colours), so that its material's colour applies.
inline constexpr std::array<std::string_view, 3> kVertexColorAttributes = {"red", "green", "blue"};
bool is_vertex_color_attribute(std::string_view name);

struct VertexAttribute {
  std::string name;
  std::vector<float> values;  // one per vertex
};

class TriangleMesh {
 public:
  using Triangle = std::array<std::uint32_t, 3>;

  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;  // unit length
  std::vector<Eigen::Vector2f> uvs;
  std::vector<Triangle> triangles;  // counter-clockwise seen from outside
  std::vector<Material> materials;  // one per triangle
  std::vector<VertexAttribute> attributes;

  // Bytes of a mesh of that size: per vertex a position, a normal, a texture coordinate and a
  // float per attribute; per triangle three indices and a material. Checked against the memory
  // limit before a mesh is allocated.
  static double bytes_for(std::size_t vertices, std::size_t triangles, std::size_t attributes);

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }

  // Adds (or returns the existing) attribute column; new columns are sized to the vertices.
  std::vector<float>& add_attribute(const std::string& name);
  bool has_attribute(std::string_view name) const;
  // Throws ValueError naming the known attributes when there is no such column.
  std::span<const float> attribute(std::string_view name) const;
  std::vector<std::string> attribute_names() const;

  // Triangles of one material, in order (the mesher emits bark first, then leaves).
  std::size_t triangle_count(Material material) const;

  // Appends `other`, offsetting its indices; attributes missing on either side are filled with 0
  // (vertex colours with NaN: no colour of their own).
  void append(const TriangleMesh& other);
  // All three vertex colour attributes are there.
  bool has_vertex_colors() const;

  // Axis-aligned bounds of the positions (zero when empty).
  Eigen::Vector3f bbox_min() const;
  Eigen::Vector3f bbox_max() const;
};

// Each vertex's colour: its own where it has one (kVertexColorAttributes), else the material
// colour of the first triangle that uses it (bark for a vertex no triangle uses).
std::vector<std::array<float, 3>> resolved_vertex_colors(const TriangleMesh& mesh);

}  // namespace fspm::graphics
