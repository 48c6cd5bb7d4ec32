// Bone weights against Reynolds et al. 2011, 3.2; linear blend skinning of the continuous mesh
// (written here, independently of the library); the skinned .glb read back by a minimal reader.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <set>

#include "graphics/skeleton_skin.hpp"
#include "graphics/tree_mesher.hpp"
#include "tests/graphics/mesh_checks.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

TriangleMesh continuous_mesh(const TreeGraph& tree) {
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  return mesh_tree(tree, o);
}

// The bone weights of vertex v, read from the attribute columns (bone id -> weight).
std::map<int, float> weights_of(const TriangleMesh& mesh, std::size_t v) {
  std::map<int, float> out;
  for (int k = 0; k < 4; ++k) {
    const float w = mesh.attribute("weight" + std::to_string(k))[v];
    const float b = mesh.attribute("bone" + std::to_string(k))[v];
    if (w > 0.0f) out[static_cast<int>(b)] += w;
  }
  return out;
}

bool on_trunk_surface(const Eigen::Vector3f& p) {
  return std::abs(p.head<2>().norm() - 0.1f) < 1e-4f && p.z() > 1e-4f && p.z() < 4.0f - 1e-4f;
}

// Trunk-surface vertices used by a triangle that also reaches off the trunk: the corners of the
// quads the laterals grow out of (Reynolds' shared vertices).
std::set<std::uint32_t> junction_vertices(const TriangleMesh& mesh) {
  std::set<std::uint32_t> out;
  for (const auto& tri : mesh.triangles) {
    bool off = false;
    for (auto v : tri) off |= mesh.positions[v].head<2>().norm() > 0.101f;
    if (!off) continue;
    for (auto v : tri) {
      if (on_trunk_surface(mesh.positions[v])) out.insert(v);
    }
  }
  return out;
}

TEST(BoneWeights, FollowReynoldsRules) {
  const TreeGraph tree = testing::junction_tree();
  const TriangleMesh mesh = continuous_mesh(tree);
  std::size_t joints = 0, tips = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const auto w = weights_of(mesh, v);
    float sum = 0.0f;
    for (const auto& [bone, weight] : w) sum += weight;
    ASSERT_NEAR(sum, 1.0f, 1e-6f) << "vertex " << v;
    const Eigen::Vector3f p = mesh.positions[v];
    if (on_trunk_surface(p) && std::abs(p.z() - 1.0f) < 1e-5f) {  // joint of nodes 0 and 1
      ++joints;
      EXPECT_EQ(w, (std::map<int, float>{{0, 0.5f}, {1, 0.5f}})) << "vertex " << v;
    }
    if (std::abs(p.z() - 4.0f) < 1e-5f) {  // trunk tip ring, cap and hub
      ++tips;
      EXPECT_EQ(w, (std::map<int, float>{{3, 1.0f}})) << "vertex " << v;
    }
  }
  EXPECT_GT(joints, 3u);
  EXPECT_GT(tips, 3u);
  // Lateral tips (nodes 5 and 7): 1.0 from their last bone.
  for (NodeId tip : {NodeId{5}, NodeId{7}}) {
    const Eigen::Vector3f end = tree.end(tip).cast<float>();
    const Eigen::Vector3f dir = (tree.end(tip) - tree.start(tip)).normalized().cast<float>();
    std::size_t n = 0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      if (std::abs((mesh.positions[v] - end).dot(dir)) > 1e-5f) continue;
      if ((mesh.positions[v] - end).norm() > 0.031f) continue;
      ++n;
      EXPECT_EQ(weights_of(mesh, v), (std::map<int, float>{{static_cast<int>(tip), 1.0f}}));
    }
    EXPECT_GT(n, 3u);
  }
}

TEST(BoneWeights, SharedJunctionVerticesAccumulateBothLimbs) {
  // Reynolds: shared vertices accumulate the parent ring's influence (0.5 + 0.5 at a joint ring,
  // 1.0 on a knuckle ring) and the lateral's root (1.0), then scale to 1: the lateral's first
  // bone gets 0.5 and the trunk bones the other 0.5 (0.25 + 0.25, or 0.5 on a knuckle).
  const TreeGraph tree = testing::junction_tree();
  const TriangleMesh mesh = continuous_mesh(tree);
  const std::set<std::uint32_t> shared = junction_vertices(mesh);
  std::size_t at_lateral[2] = {0, 0};
  for (std::uint32_t v : shared) {
    const auto w = weights_of(mesh, v);
    const int lateral = mesh.positions[v].z() < 2.6f ? 4 : 6;  // first bones of the laterals
    ++at_lateral[lateral == 4 ? 0 : 1];
    ASSERT_TRUE(w.count(lateral)) << "vertex " << v;
    EXPECT_FLOAT_EQ(w.at(lateral), 0.5f);
    float trunk = 0.0f;
    for (const auto& [bone, weight] : w) {
      if (bone == lateral) continue;
      EXPECT_LE(bone, 3) << "only trunk bones besides the lateral";
      EXPECT_TRUE(weight == 0.25f || weight == 0.5f) << weight;
      trunk += weight;
    }
    EXPECT_FLOAT_EQ(trunk, 0.5f);
  }
  EXPECT_GE(at_lateral[0], 4u);  // the four corners of each open quad (and their copies)
  EXPECT_GE(at_lateral[1], 4u);
}

// Rotation by `angle` about `axis` through `pivot`, as a 4x4 matrix.
Eigen::Matrix4f rotation_about(const Eigen::Vector3f& pivot, const Eigen::Vector3f& axis,
                               float angle) {
  Eigen::Affine3f a = Eigen::Translation3f(pivot) * Eigen::AngleAxisf(angle, axis.normalized()) *
                      Eigen::Translation3f(-pivot);
  return a.matrix();
}

// Linear blend skinning written out here: v' = sum_k w_k M_{j_k} v.
TriangleMesh blend(const TriangleMesh& mesh, const Skin& skin,
                   const std::vector<Eigen::Matrix4f>& skinning) {
  TriangleMesh out = mesh;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    Eigen::Vector4f p = Eigen::Vector4f::Zero();
    for (int k = 0; k < 4; ++k) {
      p += skin.weights[v][k] * (skinning[skin.joints[v][k]] * mesh.positions[v].homogeneous());
    }
    out.positions[v] = p.head<3>();
  }
  return out;
}

// Directed edges of the bark with no reverse after welding equal positions.
std::size_t open_edges(const TriangleMesh& mesh) {
  std::map<std::array<float, 3>, std::uint32_t> weld;
  std::vector<std::uint32_t> id(mesh.vertex_count());
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    const auto& p = mesh.positions[i];
    id[i] = weld.emplace(std::array<float, 3>{p.x(), p.y(), p.z()}, weld.size()).first->second;
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kBark) continue;
    for (int k = 0; k < 3; ++k) {
      edges.insert({id[mesh.triangles[t][k]], id[mesh.triangles[t][(k + 1) % 3]]});
    }
  }
  std::size_t open = 0;
  for (const auto& [a, b] : edges) open += !edges.count({b, a});
  return open;
}

TEST(SkeletonSkin, RotatingOneBoneKeepsEveryJunctionClosed) {
  const TreeGraph tree = testing::junction_tree();
  const TriangleMesh mesh = continuous_mesh(tree);
  const Skin skin = skin_mesh(tree, mesh);
  ASSERT_EQ(skin.skeleton.size(), 8u);  // one joint per internode
  // Rigidly rotate lateral A's first bone (node 4) and, with it, its child (node 5).
  const Eigen::Vector3f pivot = tree.start(4).cast<float>();
  const Eigen::Matrix4f r = rotation_about(pivot, Eigen::Vector3f(-0.4f, 1, 0), 0.5f);
  std::vector<Eigen::Matrix4f> skinning(skin.skeleton.size(), Eigen::Matrix4f::Identity());
  for (std::size_t j = 0; j < skin.skeleton.size(); ++j) {
    const NodeId n = skin.skeleton.nodes[j];
    if (n == 4 || n == 5) skinning[j] = r;
  }
  const TriangleMesh posed = blend(mesh, skin, skinning);
  testing::expect_closed_bark(posed);
  EXPECT_EQ(open_edges(posed), 0u);
  // The lateral did move: its tip by the rotation of a point 1.2 m from the pivot.
  const Eigen::Vector3f tip = tree.end(5).cast<float>();
  const Eigen::Vector3f moved = (r * tip.homogeneous()).head<3>();
  float nearest = 1e9f;
  for (const auto& p : posed.positions) nearest = std::min(nearest, (p - moved).norm());
  EXPECT_LT(nearest, 0.031f);  // a tip ring vertex within the lateral's radius
  EXPECT_GT((moved - tip).norm(), 0.5f);

  // The check can fail: one copy of a shared corner following the lateral alone opens the seam.
  Skin broken = skin;
  const std::set<std::uint32_t> shared = junction_vertices(mesh);
  std::map<std::array<float, 3>, int> at_position;
  for (const auto& p : mesh.positions) ++at_position[{p.x(), p.y(), p.z()}];
  bool changed = false;
  for (std::uint32_t v : shared) {
    const auto& p = mesh.positions[v];
    if (at_position[{p.x(), p.y(), p.z()}] < 2 || p.z() > 2.6f) continue;
    broken.joints[v] = {4, 0, 0, 0};
    broken.weights[v] = {1.0f, 0.0f, 0.0f, 0.0f};
    changed = true;
    break;
  }
  ASSERT_TRUE(changed) << "no duplicated corner found at lateral A";
  EXPECT_GT(open_edges(blend(mesh, broken, skinning)), 0u);
}

TEST(SkeletonSkin, JointWorldMatricesComposeDownTheTree) {
  const TreeGraph tree = testing::junction_tree();
  const Skeleton s = tree_skeleton(tree);
  ASSERT_EQ(s.size(), 8u);
  std::vector<Eigen::Quaternionf> q(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    q[j] = Eigen::AngleAxisf(0.1f * static_cast<float>(j + 1),
                             Eigen::Vector3f(0, 1, 0.2f).normalized());
  }
  const auto world = joint_world_matrices(s, q);
  // Independently: the skinning matrix of a joint is the product, from the root down, of
  // rotations about each ancestor's (and its own) head at rest.
  for (std::size_t j = 0; j < s.size(); ++j) {
    std::vector<NodeId> chain;
    for (NodeId n = s.nodes[j]; n != kNoNode; n = tree.parent(n)) chain.insert(chain.begin(), n);
    Eigen::Matrix4f expected = Eigen::Matrix4f::Identity();
    for (NodeId n : chain) {
      const Eigen::AngleAxisf aa(q[n]);
      expected = expected * rotation_about(tree.start(n).cast<float>(), aa.axis(), aa.angle());
    }
    const Eigen::Matrix4f got = world[j] * inverse_bind_matrices(s)[j];
    EXPECT_TRUE(got.isApprox(expected, 1e-5f)) << "joint " << j << "\n" << got << "\n" << expected;
  }
}

TEST(SkeletonSkin, LeavesFollowTheirInternode) {
  // small_tree: leaves on internodes 1 and the two branch tips; each leaf vertex takes the
  // internode it grows on at 1.0.
  const TreeGraph tree = testing::small_tree();
  MeshOptions o;
  o.junctions = JunctionMode::kContinuous;
  o.leaves = true;
  const TriangleMesh mesh = mesh_tree(tree, o);
  std::set<NodeId> bearers;
  for (NodeId id = 0; id < tree.size(); ++id) {
    if (tree.kind(id) == OrganKind::kLeaf) bearers.insert(tree.parent(id));
  }
  const Skin skin = skin_mesh(tree, mesh);
  std::vector<char> leaf_vertex(mesh.vertex_count(), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kLeaf) continue;
    for (auto v : mesh.triangles[t]) leaf_vertex[v] = 1;
  }
  std::size_t leaves = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!leaf_vertex[v]) continue;
    ++leaves;
    EXPECT_FLOAT_EQ(skin.weights[v][0], 1.0f);
    EXPECT_EQ(skin.weights[v][1] + skin.weights[v][2] + skin.weights[v][3], 0.0f);
    EXPECT_TRUE(bearers.count(skin.skeleton.nodes[skin.joints[v][0]])) << "vertex " << v;
  }
  EXPECT_EQ(leaves, 3u * 4u);  // three flat quads
}

}  // namespace
}  // namespace fspm::graphics
