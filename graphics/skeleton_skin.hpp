#pragma once
// A skin for a tree mesh (glTF 2.0 skins, section 3.7.3): one joint per internode at the
// internode's start, parented like the internodes, and per vertex up to four joints with their
// weights (the bone weights the continuous mesher assigns after Reynolds et al. 2011, 3.2).
// Linear blend skinning moves each vertex by the weighted sum of its joints' skinning matrices
// (joint world matrix times inverse bind matrix).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

// glTF JOINTS_0 as unsigned shorts: at most this many joints per skin.
inline constexpr std::size_t kMaxJoints = 65535;

struct Skeleton {
  std::vector<NodeId> nodes;             // the internode of each joint
  std::vector<int> parents;              // parent joint, -1 for a root
  std::vector<Eigen::Vector3f> heads_m;  // bind position: the internode's start
  std::vector<float> radii_m;
  std::vector<float> lengths_m;
  std::vector<std::uint16_t> orders;  // branching order: joints of one axis share it

  std::size_t size() const { return nodes.size(); }
};

struct Skin {
  Skeleton skeleton;
  std::vector<std::array<std::uint16_t, 4>> joints;  // JOINTS_0, one per vertex
  std::vector<std::array<float, 4>> weights;         // WEIGHTS_0, each summing to 1
};

// Every internode becomes a joint; its parent is the nearest internode above it. Throws
// ValueError beyond kMaxJoints.
Skeleton tree_skeleton(const TreeGraph& tree);

// The skin of a mesh of `tree` meshed with continuous junctions (vertex attributes bone0..3 and
// weight0..3). Vertices without bones (leaves, obstacles) follow the root joint. Throws
// ValueError when the mesh carries no bone weights or names a bone that is not an internode.
Skin skin_mesh(const TreeGraph& tree, const TriangleMesh& mesh);

// Bind pose: joint world matrices are translations to the heads, so the inverse bind matrices
// are translations by minus the heads (column-major 4x4, as glTF stores them).
std::vector<Eigen::Matrix4f> inverse_bind_matrices(const Skeleton& skeleton);

// World matrices of the joints from their local rotations about their heads (one per joint,
// identity = bind pose), composed down the hierarchy.
std::vector<Eigen::Matrix4f> joint_world_matrices(const Skeleton& skeleton,
                                                  const std::vector<Eigen::Quaternionf>& rotations);

// Linear blend skinning of positions and normals on the CPU; other columns are copied.
TriangleMesh pose_mesh(const TriangleMesh& mesh, const Skin& skin,
                       const std::vector<Eigen::Matrix4f>& joint_world);

}  // namespace fspm::graphics
