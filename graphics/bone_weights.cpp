// Accumulated and normalised bone weights (Reynolds et al. 2011, section 3.2).
#include "graphics/bone_weights.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "fspm/error.hpp"

namespace fspm::graphics {

void BoneWeights::add(NodeId bone, float weight) {
  for (std::size_t k = 0; k < kMaxBonesPerVertex; ++k) {
    if (bones[k] == bone) {
      weights[k] += weight;
      return;
    }
  }
  // A free slot, else the weakest if the newcomer is stronger.
  const auto weakest = std::min_element(weights.begin(), weights.end()) - weights.begin();
  const auto free = std::find(bones.begin(), bones.end(), kNoNode) - bones.begin();
  const auto slot = free < static_cast<long>(kMaxBonesPerVertex) ? free : weakest;
  if (bones[slot] != kNoNode && weights[slot] >= weight) return;
  bones[slot] = bone;
  weights[slot] = weight;
}

float BoneWeights::total() const { return std::accumulate(weights.begin(), weights.end(), 0.0f); }

void BoneWeights::normalise() {
  const float sum = total();
  if (sum <= 0.0f) return;
  std::array<std::size_t, kMaxBonesPerVertex> order{0, 1, 2, 3};
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return weights[a] > weights[b]; });
  BoneWeights sorted;
  for (std::size_t k = 0; k < kMaxBonesPerVertex; ++k) {
    if (bones[order[k]] == kNoNode || weights[order[k]] <= 0.0f) continue;
    sorted.bones[k] = bones[order[k]];
    sorted.weights[k] = weights[order[k]] / sum;
  }
  *this = sorted;
}

BoneWeights joint_weights(NodeId below, NodeId above) {
  BoneWeights w;
  if (below == above) {
    w.add(below, 1.0f);
  } else {
    w.add(below, 0.5f);
    w.add(above, 0.5f);
  }
  return w;
}

void write_bone_attributes(const std::vector<BoneWeights>& weights, TriangleMesh& mesh) {
  for (std::size_t k = 0; k < kMaxBonesPerVertex; ++k) {
    auto& bone = mesh.add_attribute("bone" + std::to_string(k));
    auto& weight = mesh.add_attribute("weight" + std::to_string(k));
    for (std::size_t v = 0; v < weights.size() && v < bone.size(); ++v) {
      const NodeId b = weights[v].bones[k];
      bone[v] = b == kNoNode ? -1.0f : static_cast<float>(b);
      weight[v] = weights[v].weights[k];
    }
  }
}

std::vector<BoneWeights> read_bone_attributes(const TriangleMesh& mesh) {
  if (!mesh.has_attribute("bone0") || !mesh.has_attribute("weight0")) {
    throw ValueError("the mesh has no bone weights (mesh it with continuous junctions)");
  }
  std::vector<BoneWeights> out(mesh.vertex_count());
  for (std::size_t k = 0; k < kMaxBonesPerVertex; ++k) {
    const std::string suffix = std::to_string(k);
    if (!mesh.has_attribute("bone" + suffix)) break;
    const auto bone = mesh.attribute("bone" + suffix);
    const auto weight = mesh.attribute("weight" + suffix);
    for (std::size_t v = 0; v < out.size(); ++v) {
      if (bone[v] < 0.0f || weight[v] <= 0.0f) continue;
      out[v].bones[k] = static_cast<NodeId>(bone[v]);
      out[v].weights[k] = weight[v];
    }
  }
  return out;
}

}  // namespace fspm::graphics
