#include "fspm/tree_graph.hpp"

#include <gtest/gtest.h>

#include <random>

#include "fspm/error.hpp"
#include "tests/fspm/random_tree.hpp"

namespace fspm {
namespace {

// root(0) -> a(1) -> c(3); root -> b(2)
TreeGraph small_tree() {
  TreeGraph t;
  NodeData d;
  d.end = {0, 0, 1};
  t.add_node(kNoNode, d);
  d.start = {0, 0, 1};
  d.end = {0, 0, 3};
  t.add_node(0, d);
  d.end = {1, 0, 1};
  d.order = 1;
  t.add_node(0, d);
  d.start = {0, 0, 3};
  d.end = {0, 0, 4};
  d.order = 0;
  t.add_node(1, d);
  return t;
}

TEST(TreeGraph, LinksChildrenInInsertionOrder) {
  const TreeGraph t = small_tree();
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t.parent(0), kNoNode);
  EXPECT_EQ(t.first_child(0), 1u);
  EXPECT_EQ(t.next_sibling(1), 2u);
  EXPECT_EQ(t.child_count(0), 2u);
  EXPECT_TRUE(t.is_tip(2));
  std::vector<NodeId> kids(t.children(0).begin(), t.children(0).end());
  EXPECT_EQ(kids, (std::vector<NodeId>{1, 2}));
}

TEST(TreeGraph, DerivesLengthAndDirectionFromSegment) {
  const TreeGraph t = small_tree();
  EXPECT_DOUBLE_EQ(t.length(1), 2.0);
  EXPECT_DOUBLE_EQ(t.direction(1).z(), 1.0);
  EXPECT_DOUBLE_EQ(t.length(2), 1.0);
  EXPECT_DOUBLE_EQ(t.direction(2).x(), 1.0);
  TreeGraph u;
  NodeData d;
  d.end = {1, 1, 0};
  u.add_node(kNoNode, d);
  EXPECT_DOUBLE_EQ(u.length(0), std::sqrt(2.0));
  EXPECT_NEAR(u.direction(0).y(), std::sqrt(0.5), 1e-15);
}

TEST(TreeGraph, RejectsSecondRootAndUnknownParent) {
  TreeGraph t = small_tree();
  EXPECT_THROW(t.add_node(kNoNode, {}), ValueError);
  EXPECT_THROW(t.add_node(17, {}), ValueError);
}

TEST(TreeGraph, AttributesGetDefaultsAndThrowWhenMissing) {
  TreeGraph t = small_tree();
  t.add_attribute("light", 0.5);
  EXPECT_EQ(t.attribute("light").size(), 4u);
  EXPECT_DOUBLE_EQ(t.attribute("light")[3], 0.5);
  t.attribute("light")[3] = 0.9;
  t.add_node(3, {});
  EXPECT_DOUBLE_EQ(t.attribute("light")[4], 0.5);
  EXPECT_DOUBLE_EQ(t.attribute("light")[3], 0.9);
  EXPECT_THROW(t.attribute("nope"), ValueError);
}

TEST(TreeGraph, RemoveSubtreeCompactsAndKeepsOrder) {
  TreeGraph t = small_tree();
  t.add_attribute("tag", 0.0);
  for (NodeId n = 0; n < t.size(); ++n) t.attribute("tag")[n] = n;
  const auto remap = t.remove_subtree(1);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(remap[0], 0u);
  EXPECT_EQ(remap[1], kNoNode);
  EXPECT_EQ(remap[3], kNoNode);
  EXPECT_EQ(remap[2], 1u);
  EXPECT_DOUBLE_EQ(t.attribute("tag")[1], 2.0);
  EXPECT_EQ(t.parent(1), 0u);
  EXPECT_EQ(t.child_count(0), 1u);
}

TEST(TreeGraph, CopyAndAppendSubtreeRoundTrip) {
  const TreeGraph t = small_tree();
  const TreeGraph sub = t.copy_subtree(1);
  ASSERT_EQ(sub.size(), 2u);
  EXPECT_EQ(sub.parent(1), 0u);
  EXPECT_DOUBLE_EQ(sub.length(1), 1.0);
  TreeGraph u = small_tree();
  u.remove_subtree(1);
  const NodeId r = u.append_subtree(0, sub);
  EXPECT_EQ(u.size(), 4u);
  EXPECT_EQ(u.parent(r), 0u);
  EXPECT_EQ(u.parent(r + 1), r);
}

TEST(TreeGraph, IdenticalDetectsAnyDifference) {
  std::mt19937_64 rng(3);
  const TreeGraph a = testing::random_tree(rng, 50);
  TreeGraph b = a;
  EXPECT_TRUE(a.identical(b));
  b.set_radius(17, b.radius(17) + 1e-12);
  EXPECT_FALSE(a.identical(b));
}

TEST(TreeGraph, ParentsAlwaysPrecedeChildren) {
  std::mt19937_64 rng(5);
  const TreeGraph t = testing::random_tree(rng, 500);
  for (NodeId n = 1; n < t.size(); ++n) EXPECT_LT(t.parent(n), n);
}

}  // namespace
}  // namespace fspm
