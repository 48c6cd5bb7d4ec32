#include "experiments/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fspm::experiments {
namespace {

NodeData segment(Eigen::Vector3d a, Eigen::Vector3d b, std::uint16_t order = 0,
                 OrganKind kind = OrganKind::kInternode) {
  NodeData d;
  d.start = a;
  d.end = b;
  d.order = order;
  d.kind = kind;
  return d;
}

// A trunk of two unit internodes up z, a lateral of length 2 along x at the top of the first
// and one along -y of length 1 at the top: hand-computed figures.
TEST(Metrics, HandBuiltTree) {
  TreeGraph t;
  const NodeId a = t.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  const NodeId b = t.add_node(a, segment({0, 0, 1}, {0, 0, 2}));
  t.add_node(a, segment({0, 0, 1}, {2, 0, 1}, 1));
  t.add_node(b, segment({0, 0, 2}, {0, -1, 2}, 1));
  NodeData leaf = segment({0, -1, 2}, {0, -1, 2.5}, 1, OrganKind::kLeaf);
  leaf.length = 0.5;
  t.add_node(3, leaf);
  const auto m = tree_metrics(t);
  EXPECT_EQ(m.at("nodes"), 5);
  EXPECT_EQ(m.at("internodes"), 4);
  EXPECT_EQ(m.at("leaves"), 1);
  EXPECT_EQ(m.at("max_order"), 1);
  EXPECT_DOUBLE_EQ(m.at("height"), 2.5);
  EXPECT_DOUBLE_EQ(m.at("total_length"), 1 + 1 + 2 + 1);
  // Ground projection: (0,0), (2,0), (0,-1): diameter = |(2,0) - (0,-1)| = sqrt(5).
  EXPECT_DOUBLE_EQ(m.at("crown_width"), std::sqrt(5.0));
  // Crown base at z = 1 (the lowest lateral), top at 2.5.
  EXPECT_DOUBLE_EQ(m.at("crown_depth"), 1.5);
  EXPECT_EQ(m.at("leaf_area"), 0.0);
}

TEST(Metrics, BareTrunkHasNoCrown) {
  TreeGraph t;
  t.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 3}));
  const auto m = tree_metrics(t);
  EXPECT_EQ(m.at("crown_depth"), 0.0);
  EXPECT_EQ(m.at("crown_width"), 0.0);
  EXPECT_EQ(m.at("height"), 3.0);
}

TEST(Metrics, EveryMetricHasAUnit) {
  for (const MetricInfo& m : metric_catalog()) {
    EXPECT_FALSE(m.unit.empty()) << m.name;
    EXPECT_EQ(find_metric(m.name), &m);
  }
  EXPECT_EQ(find_metric("no_such_metric"), nullptr);
}

}  // namespace
}  // namespace fspm::experiments
