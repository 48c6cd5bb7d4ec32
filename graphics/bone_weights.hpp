#pragma once
// Bone weights of one vertex after Reynolds et al. 2011, section 3.2: a ring around a bone joint
// takes 0.5 from each of the two bones meeting there, a ring at a branch end 1.0 from its one
// bone; where a lateral grows out of its parent the vertices are shared, the influences of both
// limbs are accumulated and, once all are assigned, scaled to total 1. At most four bones are
// kept per vertex (the glTF JOINTS_0 / WEIGHTS_0 layout); a fifth replaces the weakest if it is
// stronger.
#include <array>
#include <cstddef>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

inline constexpr std::size_t kMaxBonesPerVertex = 4;

struct BoneWeights {
  std::array<NodeId, kMaxBonesPerVertex> bones{kNoNode, kNoNode, kNoNode, kNoNode};
  std::array<float, kMaxBonesPerVertex> weights{0.0f, 0.0f, 0.0f, 0.0f};

  // Adds `weight` of `bone` (merged with the same bone's earlier influence).
  void add(NodeId bone, float weight);
  // Scales the weights to sum to 1 and sorts them strongest first; unused slots keep kNoNode
  // and 0. Leaves an empty set empty.
  void normalise();
  float total() const;
};

// Reynolds' ring rule: 0.5 from each of `below` and `above` at a joint, 1.0 at a branch end
// (below == above).
BoneWeights joint_weights(NodeId below, NodeId above);

// The weights as the mesh attributes bone0..bone3 (node ids of the bones, -1 for an unused slot;
// exact while ids stay below 2^24) and weight0..weight3, strongest first.
void write_bone_attributes(const std::vector<BoneWeights>& weights, TriangleMesh& mesh);

// Back from those attributes; throws ValueError when the mesh has none (not meshed with
// continuous junctions). Vertices without bones (leaves) come back empty.
std::vector<BoneWeights> read_bone_attributes(const TriangleMesh& mesh);

}  // namespace fspm::graphics
