#pragma once
// Instanced meshes (Jaeger 3.1.2): each substructure of a compressed graph is meshed once, in its
// own frame, and placed by rigid transforms wherever the plant repeats it; a scene of many trees
// places whole plants the same way. Renderers draw the shared meshes with instanced draws, the
// .glb writer stores each mesh once and references it from many nodes, and flatten() gives the
// explicit mesh for formats without instancing (OBJ, PLY, VTP).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fspm/instanced_tree.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

// A plant as prototypes and transforms (fspm/instanced_tree.hpp): what
// greenlab::reconstruct_instanced and lsystem::interpret_instanced produce.
using InstancedTree = fspm::InstancedTree;

// One placement of a shared mesh: x_world = linear * x_mesh + translation, linear a rotation
// times a uniform scale.
struct MeshInstance {
  std::uint32_t mesh = 0;
  Eigen::Matrix3f linear = Eigen::Matrix3f::Identity();
  Eigen::Vector3f translation = Eigen::Vector3f::Zero();
  // Branching order of the substructure's base in the whole plant: added to the mesh's "order"
  // attribute when flattening (prototype meshes carry the order within their substructure).
  float order_offset = 0.0f;

  // Column-major 4x4 matrix (glTF and OpenGL layout).
  Eigen::Matrix4f matrix() const;
};

struct InstancedMesh {
  std::vector<TriangleMesh> meshes;  // each stored once
  std::vector<MeshInstance> instances;

  // A single mesh placed once at the origin.
  static InstancedMesh single(TriangleMesh mesh);

  // Of the explicit scene (every instance counted).
  std::size_t vertex_count() const;
  std::size_t triangle_count() const;
  // Of the shared meshes (each counted once): what is stored and uploaded.
  std::size_t stored_vertex_count() const;
  std::size_t stored_triangle_count() const;

  // Exact bounds of the placed vertices (zero when empty).
  void bounds(Eigen::Vector3f& lo, Eigen::Vector3f& hi) const;

  // The explicit mesh: every instance's vertices transformed (normals rotated), the "order"
  // attribute offset by the instance's order. Throws ValueError past 2^32 vertices.
  TriangleMesh flatten() const;
};

// Meshes every prototype once (with MeshOptions; a camera for level of detail is ignored, the
// prototypes having no place of their own) and lists one instance per substructure occurrence,
// parents before children. The prototypes' tubes are split where children attach, as the
// explicit tree's chains are, so flatten() has the triangle count of mesh_tree on the expanded
// tree; ring orientations and leaf blades (oriented against the world's up) may differ slightly.
// Exception: a child hanging from the tip of its parent's axis continues the parent's tube in the
// explicit tree but starts its own here, as does a child attached to no node (kNoNode). Each
// child adds its `order` to the "order" attribute of everything it places. Throws ValueError for
// bad options or a child referring to a missing prototype or node, or more than kMaxInstances
// instances.
InstancedMesh mesh_instanced(const InstancedTree& tree, const MeshOptions& options = {});

inline constexpr std::size_t kMaxInstances = std::size_t{1} << 26;

// Places parts: each part's meshes are added once, and for each placement (part index, rotation
// times uniform scale, translation) all of the part's instances are composed with it. Throws
// ValueError for a part index out of range or more than kMaxInstances instances.
struct PartPlacement {
  std::size_t part = 0;
  Eigen::Matrix3f linear = Eigen::Matrix3f::Identity();
  Eigen::Vector3f translation = Eigen::Vector3f::Zero();
};
InstancedMesh place_parts(const std::vector<InstancedMesh>& parts,
                          const std::vector<PartPlacement>& placements);

}  // namespace fspm::graphics
