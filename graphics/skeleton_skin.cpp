// Joints from the tree skeleton, vertex joints and weights, bind matrices and linear blend
// skinning.
#include "graphics/skeleton_skin.hpp"

#include <string>

#include "fspm/error.hpp"
#include "graphics/bone_weights.hpp"

namespace fspm::graphics {

Skeleton tree_skeleton(const TreeGraph& tree) {
  Skeleton s;
  // Joint of each node's nearest internode at or above it (parents precede children).
  std::vector<int> joint_of(tree.size(), -1);
  for (NodeId id = 0; id < tree.size(); ++id) {
    const NodeId p = tree.parent(id);
    const int above = p == kNoNode ? -1 : joint_of[p];
    if (tree.kind(id) != OrganKind::kInternode) {
      joint_of[id] = above;
      continue;
    }
    if (s.size() >= kMaxJoints) {
      throw ValueError("a glTF skin holds at most " + std::to_string(kMaxJoints) +
                       " joints; this tree has more internodes");
    }
    joint_of[id] = static_cast<int>(s.size());
    s.nodes.push_back(id);
    s.parents.push_back(above);
    s.heads_m.push_back(tree.start(id).cast<float>());
    s.radii_m.push_back(static_cast<float>(tree.radius(id)));
    s.lengths_m.push_back(static_cast<float>((tree.end(id) - tree.start(id)).norm()));
    s.orders.push_back(tree.order(id));
  }
  return s;
}

Skin skin_mesh(const TreeGraph& tree, const TriangleMesh& mesh) {
  Skin skin;
  skin.skeleton = tree_skeleton(tree);
  std::vector<int> joint_of_node(tree.size(), -1);
  for (std::size_t j = 0; j < skin.skeleton.size(); ++j) {
    joint_of_node[skin.skeleton.nodes[j]] = static_cast<int>(j);
  }
  const std::vector<BoneWeights> bones = read_bone_attributes(mesh);
  skin.joints.assign(mesh.vertex_count(), {0, 0, 0, 0});
  skin.weights.assign(mesh.vertex_count(), {1.0f, 0.0f, 0.0f, 0.0f});
  for (std::size_t v = 0; v < bones.size(); ++v) {
    if (bones[v].total() <= 0.0f) continue;  // no bone: the root joint at 1.0
    for (std::size_t k = 0; k < kMaxBonesPerVertex; ++k) {
      const NodeId b = bones[v].bones[k];
      if (b == kNoNode) {
        skin.weights[v][k] = 0.0f;
        continue;
      }
      if (b >= tree.size() || joint_of_node[b] < 0) {
        throw ValueError("vertex " + std::to_string(v) + " names bone " + std::to_string(b) +
                         ", which is not an internode of the tree");
      }
      skin.joints[v][k] = static_cast<std::uint16_t>(joint_of_node[b]);
      skin.weights[v][k] = bones[v].weights[k];
    }
  }
  return skin;
}

std::vector<Eigen::Matrix4f> inverse_bind_matrices(const Skeleton& skeleton) {
  std::vector<Eigen::Matrix4f> out(skeleton.size(), Eigen::Matrix4f::Identity());
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    out[j].block<3, 1>(0, 3) = -skeleton.heads_m[j];
  }
  return out;
}

std::vector<Eigen::Matrix4f> joint_world_matrices(
    const Skeleton& skeleton, const std::vector<Eigen::Quaternionf>& rotations) {
  if (rotations.size() != skeleton.size()) {
    throw ValueError("one rotation per joint expected (" + std::to_string(skeleton.size()) +
                     "), got " + std::to_string(rotations.size()));
  }
  std::vector<Eigen::Matrix4f> world(skeleton.size());
  for (std::size_t j = 0; j < skeleton.size(); ++j) {
    // Local transform: translation from the parent's head to this head, then the rotation.
    const int p = skeleton.parents[j];
    const Eigen::Vector3f offset =
        p < 0 ? skeleton.heads_m[j] : Eigen::Vector3f(skeleton.heads_m[j] - skeleton.heads_m[p]);
    Eigen::Matrix4f local = Eigen::Matrix4f::Identity();
    local.block<3, 3>(0, 0) = rotations[j].normalized().toRotationMatrix();
    local.block<3, 1>(0, 3) = offset;
    world[j] = p < 0 ? local : Eigen::Matrix4f(world[p] * local);  // parents come first
  }
  return world;
}

TriangleMesh pose_mesh(const TriangleMesh& mesh, const Skin& skin,
                       const std::vector<Eigen::Matrix4f>& joint_world) {
  if (skin.joints.size() != mesh.vertex_count() || joint_world.size() != skin.skeleton.size()) {
    throw ValueError("the skin does not belong to this mesh");
  }
  const std::vector<Eigen::Matrix4f> inverse_bind = inverse_bind_matrices(skin.skeleton);
  std::vector<Eigen::Matrix4f> skinning(joint_world.size());
  for (std::size_t j = 0; j < skinning.size(); ++j) skinning[j] = joint_world[j] * inverse_bind[j];
  TriangleMesh out = mesh;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    Eigen::Matrix4f m = Eigen::Matrix4f::Zero();
    for (std::size_t k = 0; k < 4; ++k) {
      if (skin.weights[v][k] > 0.0f) m += skin.weights[v][k] * skinning[skin.joints[v][k]];
    }
    out.positions[v] = m.block<3, 3>(0, 0) * mesh.positions[v] + m.block<3, 1>(0, 3);
    const Eigen::Vector3f n = m.block<3, 3>(0, 0) * mesh.normals[v];
    if (n.norm() > 0.0f) out.normals[v] = n.normalized();
  }
  return out;
}

}  // namespace fspm::graphics
