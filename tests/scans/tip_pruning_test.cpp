// Short side tips removed from a skeleton (scans/tip_pruning.hpp), on a hand-built tree.
#include <gtest/gtest.h>

#include "scans/tip_pruning.hpp"

namespace fspm::scans {
namespace {

NodeId add(TreeGraph& t, NodeId parent, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
           std::uint16_t order) {
  NodeData d;
  d.start = a, d.end = b, d.order = order;
  return t.add_node(parent, d);
}

// A trunk of four 1 m nodes; a 0.1 m side tip at 1 m; at 2 m a branch of 0.6 m (three nodes)
// carrying a 0.05 m side tip of its own; the trunk's last node is only 0.1 m long.
TEST(TipPruning, RemovesShortSideTipsAndKeepsAxesAndBranches) {
  TreeGraph t;
  const NodeId t0 = add(t, kNoNode, {0, 0, 0}, {0, 0, 1}, 0);
  const NodeId t1 = add(t, t0, {0, 0, 1}, {0, 0, 2}, 0);
  add(t, t0, {0, 0, 1}, {0.1, 0, 1}, 1);                    // short side tip: removed
  const NodeId t2 = add(t, t1, {0, 0, 2}, {0, 0, 2.1}, 0);  // short, but the trunk's top: kept
  const NodeId b0 = add(t, t1, {0, 0, 2}, {0.2, 0, 2}, 1);
  const NodeId b1 = add(t, b0, {0.2, 0, 2}, {0.4, 0, 2}, 1);
  add(t, b1, {0.4, 0, 2}, {0.6, 0, 2}, 1);
  add(t, b0, {0.2, 0, 2}, {0.2, 0.05, 2}, 2);  // short side tip of the branch: removed
  const TreeGraph p = without_short_tips(t, 0.3);
  ASSERT_EQ(p.size(), t.size() - 2);
  double reach = 0.0, top = 0.0;
  for (NodeId u = 0; u < p.size(); ++u) {
    reach = std::max(reach, p.end(u).x()), top = std::max(top, p.end(u).z());
    EXPECT_LT(p.end(u).y(), 0.01);
    EXPECT_FALSE(p.end(u).x() > 0.05 && p.end(u).z() < 1.5) << u;
  }
  EXPECT_NEAR(reach, 0.6, 1e-12);
  EXPECT_NEAR(top, 2.1, 1e-12);
  (void)t2;
}

}  // namespace
}  // namespace fspm::scans
