// LineTree: single-precision component list; conversions to and from TreeGraph keep the structure
// and the values to single precision.
#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "fspm/line_tree.hpp"

namespace fspm {
namespace {

TreeGraph small_plant() {
  TreeGraph t;
  t.add_attribute("dead", 0.0);
  NodeData d;
  d.start = {0, 0, 0};
  d.end = {0, 0, 2};
  d.radius = 0.1;
  d.birth_time = 1.5;
  t.add_node(kNoNode, d);
  d.start = {0, 0, 2};
  d.end = {0, 0, 3};
  d.physiological_age = 2;
  t.add_node(0, d);
  NodeData leaf;
  leaf.start = {0, 0, 2};
  leaf.direction = {1, 0, 0};
  leaf.length = 0.25;
  leaf.end = {0.25, 0, 2};
  leaf.kind = OrganKind::kLeaf;
  leaf.order = 1;
  t.add_node(0, leaf);
  t.attribute("dead")[2] = 1.0;
  return t;
}

TEST(LineTree, FromTreeGraphKeepsEveryColumn) {
  const TreeGraph t = small_plant();
  const LineTree lines = LineTree::from_tree_graph(t);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines.parents()[0], kNoNode);
  EXPECT_EQ(lines.parents()[2], 0u);
  EXPECT_EQ(lines.lengths()[0], 2.0f);  // derived by TreeGraph from start and end
  EXPECT_EQ(lines.directions()[0], Eigen::Vector3f(0, 0, 1));
  EXPECT_EQ(lines.end(2), Eigen::Vector3f(0.25f, 0, 2));
  EXPECT_EQ(lines.kinds()[2], OrganKind::kLeaf);
  EXPECT_EQ(lines.orders()[2], 1);
  EXPECT_EQ(lines.physiological_ages()[1], 2);
  EXPECT_EQ(lines.birth_times()[0], 1.5f);
  EXPECT_EQ(lines.radii()[1], 0.1f);
  ASSERT_TRUE(lines.has_dead());
  EXPECT_EQ(lines.dead()[2], 1);
  EXPECT_EQ(lines.dead()[1], 0);
}

TEST(LineTree, ToTreeGraphRebuildsTopologyAndEnds) {
  const TreeGraph back = LineTree::from_tree_graph(small_plant()).to_tree_graph();
  ASSERT_EQ(back.size(), 3u);
  EXPECT_EQ(back.child_count(0), 2u);
  EXPECT_TRUE(back.is_tip(1));
  EXPECT_NEAR((back.end(1) - Eigen::Vector3d(0, 0, 3)).norm(), 0.0, 1e-6);
  EXPECT_NEAR((back.end(2) - Eigen::Vector3d(0.25, 0, 2)).norm(), 0.0, 1e-6);
  EXPECT_EQ(back.attribute("dead")[2], 1.0);
}

TEST(LineTree, BulkWriterAndClearKeepCapacity) {
  LineTree lines;
  lines.reserve(1000);
  lines.resize_for_overwrite(10);
  EXPECT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines.dead().size(), 0u);  // no dead column unless asked for
  lines.set_has_dead(true);
  EXPECT_EQ(lines.dead().size(), 10u);
  lines.clear();
  EXPECT_TRUE(lines.empty());
  EXPECT_GE(lines.capacity(), 1000u);
}

TEST(LineTree, ABadParentIsRefusedWhenConverted) {
  LineTree lines;
  NodeData d;
  d.length = 1.0;
  d.direction = {0, 0, 1};
  lines.add(kNoNode, d);
  lines.add(5, d);  // no node 5
  EXPECT_THROW(lines.to_tree_graph(), ValueError);
}

}  // namespace
}  // namespace fspm
