#include "fspm/tree_traversal.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/tree_summary.hpp"
#include "tests/fspm/random_tree.hpp"

namespace fspm {
namespace {

// A trunk of 4 internodes (0-1-2-3, order 0), a 2-internode branch 4-5 (order 1) on node 1 and
// a leaf 6 on node 2.
TreeGraph sample() {
  TreeGraph t;
  auto add = [&](NodeId p, Eigen::Vector3d s, Eigen::Vector3d e, int order, OrganKind k) {
    NodeData d;
    d.start = s;
    d.end = e;
    d.order = static_cast<std::uint16_t>(order);
    d.kind = k;
    return t.add_node(p, d);
  };
  add(kNoNode, {0, 0, 0}, {0, 0, 1}, 0, OrganKind::kInternode);  // 0
  add(0, {0, 0, 1}, {0, 0, 2}, 0, OrganKind::kInternode);        // 1
  add(1, {0, 0, 2}, {0, 0, 3}, 0, OrganKind::kInternode);        // 2
  add(2, {0, 0, 3}, {0, 0, 4}, 0, OrganKind::kInternode);        // 3
  add(1, {0, 0, 2}, {1, 0, 2}, 1, OrganKind::kInternode);        // 4
  add(4, {1, 0, 2}, {2, 0, 2}, 1, OrganKind::kInternode);        // 5
  add(2, {0, 0, 3}, {0, 0.5, 3}, 1, OrganKind::kLeaf);           // 6
  return t;
}

TEST(Traversal, PreorderAndPostorderOfSample) {
  const TreeGraph t = sample();
  EXPECT_EQ(preorder(t), (std::vector<NodeId>{0, 1, 2, 3, 6, 4, 5}));
  EXPECT_EQ(postorder(t), (std::vector<NodeId>{3, 6, 2, 5, 4, 1, 0}));
  EXPECT_EQ(preorder(t, 4), (std::vector<NodeId>{4, 5}));
}

TEST(Traversal, AxesFollowBranchingOrder) {
  const auto a = axes(sample());
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0], (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(a[1], (std::vector<NodeId>{4, 5}));
  EXPECT_EQ(a[2], (std::vector<NodeId>{6}));
}

TEST(Traversal, ChainsBreakAtBranchingNodes) {
  auto c = chains(sample());
  std::sort(c.begin(), c.end());
  // 0-1 then branching at 1: {2} branches at 2: {3}, {6}; {4,5}.
  const std::vector<std::vector<NodeId>> expected{{0, 1}, {2}, {3}, {4, 5}, {6}};
  EXPECT_EQ(c, expected);
}

TEST(Traversal, NodesByOrder) {
  const auto o = nodes_by_order(sample());
  ASSERT_EQ(o.size(), 2u);
  EXPECT_EQ(o[0], (std::vector<NodeId>{0, 1, 2, 3}));
  EXPECT_EQ(o[1], (std::vector<NodeId>{4, 5, 6}));
}

TEST(Traversal, OrdersArePermutationsOnRandomTrees) {
  std::mt19937_64 rng(11);
  for (int rep = 0; rep < 20; ++rep) {
    const TreeGraph t = testing::random_tree(rng, 1 + rep * 37, 0);
    const auto pre = preorder(t);
    const auto post = postorder(t);
    ASSERT_EQ(pre.size(), t.size());
    ASSERT_EQ(post.size(), t.size());
    std::vector<std::size_t> pos_pre(t.size()), pos_post(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
      pos_pre[pre[i]] = i;
      pos_post[post[i]] = i;
    }
    for (NodeId n = 1; n < t.size(); ++n) {
      EXPECT_LT(pos_pre[t.parent(n)], pos_pre[n]);
      EXPECT_GT(pos_post[t.parent(n)], pos_post[n]);
    }
    std::size_t chained = 0;
    for (const auto& ch : chains(t)) chained += ch.size();
    EXPECT_EQ(chained, t.size());
  }
}

TEST(Summary, CountsAndExtentsOfSample) {
  const TreeSummary s = summarize(sample());
  EXPECT_EQ(s.nodes, 7u);
  EXPECT_EQ(s.internodes, 6u);
  EXPECT_EQ(s.leaves, 1u);
  EXPECT_EQ(s.tips, 3u);
  EXPECT_EQ(s.max_order, 1u);
  EXPECT_EQ(s.max_depth, 3u);
  EXPECT_DOUBLE_EQ(s.height_m, 4.0);
  EXPECT_DOUBLE_EQ(s.total_length_m, 6.0);
  EXPECT_DOUBLE_EQ(s.bbox_max.x(), 2.0);
  // Ground projection: (0, 0), (1, 0), (2, 0), (0, 0.5); widest pair (2, 0)-(0, 0.5).
  EXPECT_DOUBLE_EQ(s.crown_width_m, std::sqrt(4.25));
  EXPECT_DOUBLE_EQ(s.crown_depth_m, 2.0);  // top 4 m, lowest lateral start 2 m
  EXPECT_EQ(s.branches_per_order, (std::vector<std::size_t>{1, 1}));  // the leaf is no axis
}

TEST(Summary, ANodeStartingAwayFromItsParentWidensTheCrown) {
  TreeGraph t = sample();
  NodeData d;
  d.start = {-3, 0, 1};  // starts 3 m off the trunk, ends next to it
  d.end = {0, 0, 1.5};
  d.order = 1;
  t.add_node(0, d);
  EXPECT_DOUBLE_EQ(summarize(t).crown_width_m, 5.0);  // (-3, 0) to (2, 0)
}

// The summary's scratch (depths, the ground projection and its hull) is counted with the tree it
// summarizes: a limit that holds the tree alone refuses it, one with room for both does not.
TEST(Summary, ItsScratchCountsAgainstTheMemoryLimit) {
  std::mt19937_64 rng(5);
  const TreeGraph t = testing::random_tree(rng, 20000, 0);
  const double tree_bytes =
      static_cast<double>(t.size()) * TreeGraph::bytes_per_node(t.attribute_names().size());
  set_memory_limit_bytes(static_cast<std::uint64_t>(1.05 * tree_bytes));
  EXPECT_THROW(summarize(t), MemoryLimitError);
  set_memory_limit_bytes(static_cast<std::uint64_t>(1.5 * tree_bytes));
  EXPECT_EQ(summarize(t).nodes, t.size());
  set_memory_limit_bytes(0);
}

}  // namespace
}  // namespace fspm
