// Level of detail by exploring the graph (Jaeger 3.1.1): order limit and collinear merging,
// checked against counts worked out by hand.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>

#include "fspm/instanced_lod.hpp"
#include "fspm/instanced_tree.hpp"

namespace fspm {
namespace {

// ABOP Fig. 1.24a, F -> F[+F]F[-F]F, built by hand as substructures: F^(0) is one unit
// internode up z; F^(k) places five F^(k-1) (every one hanging from what F^(k) hangs from, as the
// L-system's substructures do): the trunk thirds at heights 0, L, 2L (L = 3^(k-1)) and the two
// branches, turned by +-25.7 degrees about y, at heights L and 2L with order 1.
InstancedTree figure_1_24a(int n) {
  InstancedTree t;
  t.prototypes.resize(static_cast<std::size_t>(n) + 1);
  NodeData f;
  f.end = Eigen::Vector3d::UnitZ();
  f.direction = Eigen::Vector3d::UnitZ();
  f.length = 1.0;
  f.radius = 0.01;
  t.prototypes[static_cast<std::size_t>(n)].geometry.add_node(kNoNode, f);  // F^(0) is last
  const double angle = 25.7 * M_PI / 180.0;
  const Eigen::Matrix3d left = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).matrix();
  const Eigen::Matrix3d right = Eigen::AngleAxisd(-angle, Eigen::Vector3d::UnitY()).matrix();
  for (int k = 1; k <= n; ++k) {
    auto& p = t.prototypes[static_cast<std::size_t>(n - k)];  // F^(k); F^(n) is the root
    const auto sub = static_cast<std::uint32_t>(n - k + 1);   // F^(k-1)
    const double l = std::pow(3.0, k - 1);
    const Eigen::Matrix3d id = Eigen::Matrix3d::Identity();
    auto at = [](double z) { return Eigen::Vector3d(0.0, 0.0, z); };
    p.children = {{sub, kNoNode, id, at(0.0), 0.0},
                  {sub, kNoNode, left, at(l), 1.0},
                  {sub, kNoNode, id, at(l), 0.0},
                  {sub, kNoNode, right, at(2 * l), 1.0},
                  {sub, kNoNode, id, at(2 * l), 0.0}};
  }
  return t;
}

std::uint64_t nodes_at(const InstancedTree& t, double max_order, bool merge) {
  LevelOfDetail lod;
  lod.max_order = max_order;
  lod.merge_collinear = merge;
  const InstancedTree reduced = reduce_instanced_tree(t, lod);
  const std::uint64_t counted = count_instanced_tree(reduced).nodes;
  // The count on the reduced substructures is the size of their expansion.
  if (counted < 100000) {
    EXPECT_EQ(expand_instanced_tree(reduced, 100000).size(), counted);
  }
  return counted;
}

TEST(InstancedLod, Figure124aAtTwoStepsByHand) {
  // n = 2: 25 internodes; the trunk has 9 (3^2) with a branch at each of its 8 joints; 8
  // order-1 axes: 2 are F^(1) (3 internodes and 2 order-2 branches), 6 are single F.
  const InstancedTree t = figure_1_24a(2);
  EXPECT_EQ(nodes_at(t, LevelOfDetail::kUnlimitedOrder, false), 25u);
  EXPECT_EQ(nodes_at(t, 0, false), 9u);
  EXPECT_EQ(nodes_at(t, 1, false), 9u + 2 * 3 + 6);
  // Merged: the trunk alone is one straight internode; at order 1 the trunk keeps its 9 pieces
  // (a branch at every joint) and each F^(1) branch, bare, becomes one; at order 2 every joint
  // bears a branch and nothing merges.
  EXPECT_EQ(nodes_at(t, 0, true), 1u);
  EXPECT_EQ(nodes_at(t, 1, true), 9u + 2 + 6);
  EXPECT_EQ(nodes_at(t, 2, true), 25u);
  // The trunk stays the root: its first internode, not a branch drawn after it.
  LevelOfDetail lod;
  lod.max_order = 1;
  lod.merge_collinear = true;
  const TreeGraph g = expand_instanced_tree(reduce_instanced_tree(t, lod), 100);
  EXPECT_EQ(g.order(0), 0);
  EXPECT_EQ(g.start(0), Eigen::Vector3d::Zero());
  std::size_t long_branches = 0;
  for (NodeId n = 0; n < g.size(); ++n) long_branches += g.length(n) == 3.0 ? 1 : 0;
  EXPECT_EQ(long_branches, 2u);  // the two bare F^(1) branches, merged
}

TEST(InstancedLod, Figure124aAtTwentyStepsIsCountedWithoutExpanding) {
  const InstancedTree t = figure_1_24a(20);
  EXPECT_EQ(count_instanced_tree(t).nodes, 95367431640625u);  // 5^20
  LevelOfDetail lod;
  lod.max_order = 0;
  lod.merge_collinear = true;
  const InstancedTree trunk = reduce_instanced_tree(t, lod);
  const TreeGraph g = expand_instanced_tree(trunk, 10);
  ASSERT_EQ(g.size(), 1u);
  EXPECT_DOUBLE_EQ(g.length(0), std::pow(3.0, 20));  // 3^20 unit internodes in one
  EXPECT_NEAR((g.end(0) - Eigen::Vector3d(0, 0, std::pow(3.0, 20))).norm(), 0.0, 1e-3);
  // Order 1 merged: M(n) = 3 M(n-1) + 2 (each branch merged to one), M(0) = 1: 2 3^n - 1.
  EXPECT_EQ(nodes_at(t, 1, true), std::uint64_t{2} * 3486784401u - 1u);
  // Order 1 not merged: I(n) = 3 I(n-1) + 2 3^(n-1), I(0) = 1: (2n + 3) 3^(n-1).
  EXPECT_EQ(nodes_at(t, 1, false), std::uint64_t{43} * 1162261467u);
}

// A chain of four unit internodes up z with a leaf at the top of the second and a lateral
// internode at the top of the third; radii 4, 2, 2, 1.
TreeGraph chain_with_leaf_and_branch() {
  TreeGraph g;
  NodeData d;
  d.direction = Eigen::Vector3d::UnitZ();
  d.length = 1.0;
  NodeId parent = kNoNode;
  const double radii[] = {4.0, 2.0, 2.0, 1.0};
  for (int i = 0; i < 4; ++i) {
    d.start = Eigen::Vector3d(0, 0, i);
    d.end = Eigen::Vector3d(0, 0, i + 1);
    d.radius = radii[i];
    d.birth_time = i;
    parent = g.add_node(parent, d);
  }
  NodeData leaf;
  leaf.kind = OrganKind::kLeaf;
  leaf.order = 1;
  leaf.start = Eigen::Vector3d(0, 0, 2);
  leaf.end = Eigen::Vector3d(0.3, 0, 2);
  g.add_node(1, leaf);
  NodeData branch;
  branch.order = 1;
  branch.start = Eigen::Vector3d(0, 0, 3);
  branch.end = Eigen::Vector3d(1, 0, 3);
  g.add_node(2, branch);
  return g;
}

TEST(InstancedLod, MergingStopsWhereSomethingGrows) {
  const TreeGraph g = chain_with_leaf_and_branch();
  LevelOfDetail merge;
  merge.merge_collinear = true;
  // Joints at z = 1 (nothing), 2 (leaf), 3 (branch): only the first merges.
  const TreeGraph m = reduce_tree(g, merge);
  ASSERT_EQ(m.size(), 5u);
  EXPECT_DOUBLE_EQ(m.length(0), 2.0);
  EXPECT_DOUBLE_EQ(m.radius(0), 3.0);  // (4 + 2) / 2, length-weighted
  EXPECT_DOUBLE_EQ(m.birth_time(0), 0.0);
  EXPECT_EQ(m.end(0), Eigen::Vector3d(0, 0, 2));
  // Nodes keep their order: the merged internode, the two others, the leaf (on the merged one),
  // the branch.
  EXPECT_EQ(m.kind(3), OrganKind::kLeaf);
  EXPECT_EQ(m.parent(3), 0u);
  EXPECT_EQ(m.parent(4), 1u);
  // Without order 1 (leaf and branch) the whole chain is one internode of mean radius 9/4.
  merge.max_order = 0;
  const TreeGraph trunk = reduce_tree(g, merge);
  ASSERT_EQ(trunk.size(), 1u);
  EXPECT_DOUBLE_EQ(trunk.length(0), 4.0);
  EXPECT_DOUBLE_EQ(trunk.radius(0), 9.0 / 4.0);
  // Order 0 without merging: the four internodes.
  merge.merge_collinear = false;
  EXPECT_EQ(reduce_tree(g, merge).size(), 4u);
}

TEST(InstancedLod, BentChainsDoNotMerge) {
  TreeGraph g;
  NodeData d;
  d.end = Eigen::Vector3d(0, 0, 1);
  g.add_node(kNoNode, d);
  d.start = d.end;
  d.end = Eigen::Vector3d(0.01, 0, 2);  // 0.57 degrees off
  d.length = -1.0;
  d.direction.setZero();
  g.add_node(0, d);
  LevelOfDetail merge;
  merge.merge_collinear = true;
  EXPECT_EQ(reduce_tree(g, merge).size(), 2u);
}

}  // namespace
}  // namespace fspm
