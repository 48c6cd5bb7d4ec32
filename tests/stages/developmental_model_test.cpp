// Developmental stages (Pirk chapter 5) on trees whose stages follow in closed form from the
// equations: chain lengths (eq. 5.3-5.4), Gravelius levels (5.2.2), angles (eq. 5.5), radii
// (eq. 5.6-5.8) and the seasonal remapping (eq. 5.11).
#include "stages/developmental_model.hpp"
#include "tests/stages/edge_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

constexpr double kPi = std::numbers::pi;

using testing::edge;

Eigen::Vector3d at_angle(double deg) {  // in the x-z plane, from +z toward +x
  return {std::sin(deg * kPi / 180.0), 0.0, std::cos(deg * kPi / 180.0)};
}

double total_length(const TreeGraph& t) {
  double s = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) s += t.length(i);
  return s;
}

// A main axis of four unit edges; laterals of two unit edges at the end of edge 1 (90 degrees)
// and of edge 2 (30 degrees).
TreeGraph two_laterals() {
  TreeGraph t;
  NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  const NodeId first_base = a;
  a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  const NodeId second_base = a;
  edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  NodeId l = edge(t, first_base, at_angle(90), 1.0, 0.05);
  edge(t, l, at_angle(90), 1.0, 0.05);
  l = edge(t, second_base, at_angle(30), 1.0, 0.05);
  edge(t, l, at_angle(30), 1.0, 0.05);
  return t;
}

TEST(DevelopmentalModel, AChainGrowsAtTheConstantRateOfEquation54) {
  TreeGraph t;
  NodeId a = kNoNode;
  for (int k = 0; k < 4; ++k) a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  const DevelopmentalModel m(t);
  EXPECT_EQ(m.chain_count(), 1u);
  for (const double s : {0.1, 0.25, 0.5, 0.6, 0.9}) {
    const TreeGraph st = m.stage(s);
    EXPECT_NEAR(total_length(st), 4.0 * s, 1e-12) << s;  // l(t) = v_g t, v_g = 4
    EXPECT_EQ(st.size(), static_cast<std::size_t>(std::ceil(4.0 * s - 1e-12))) << s;
    EXPECT_NEAR(st.end(st.size() - 1).z(), 4.0 * s, 1e-12);
  }
  EXPECT_EQ(m.stage(0.0).size(), 0u);
}

TEST(DevelopmentalModel, LateralChainsStartAtTheirBranchPointAndEndTogether) {
  const TreeGraph t = two_laterals();
  const DevelopmentalModel m(t);
  ASSERT_EQ(m.chain_count(), 3u);
  // Main: rate 4. First lateral: branch point at 2 -> starts at 0.5, rate 2 / 0.5 = 4.
  // Second: branch point at 3 -> starts at 0.75, rate 2 / 0.25 = 8.
  EXPECT_DOUBLE_EQ(m.chain_rate()[0], 4.0);
  EXPECT_DOUBLE_EQ(m.chain_start()[m.chain()[4]], 0.5);
  EXPECT_DOUBLE_EQ(m.chain_rate()[m.chain()[4]], 4.0);
  EXPECT_DOUBLE_EQ(m.chain_start()[m.chain()[6]], 0.75);
  EXPECT_DOUBLE_EQ(m.chain_rate()[m.chain()[6]], 8.0);
  // Gravelius: the straight continuation keeps level 1, both laterals have level 2.
  EXPECT_EQ(m.level()[3], 1);
  EXPECT_EQ(m.level()[4], 2);
  EXPECT_EQ(m.level()[7], 2);
  // At t = 0.875 the main axis is 3.5 long, the first lateral 1.5, the second 1.0.
  EXPECT_NEAR(total_length(m.stage(0.875)), 3.5 + 1.5 + 1.0, 1e-12);
  EXPECT_EQ(m.lateral_chain_count(), 2u);
}

TEST(DevelopmentalModel, TheLastStageIsTheGivenTree) {
  const TreeGraph t = two_laterals();
  const TreeGraph st = DevelopmentalModel(t).stage(1.0);
  ASSERT_EQ(st.size(), t.size());
  for (NodeId i = 0; i < t.size(); ++i) {
    EXPECT_LT((st.start(i) - t.start(i)).norm(), 1e-12) << i;
    EXPECT_LT((st.end(i) - t.end(i)).norm(), 1e-12) << i;
    EXPECT_NEAR(st.radius(i), t.radius(i), 1e-12) << i;
  }
}

// Eq. 5.5: both laterals start at their level's mean angle, 60 degrees, and turn at a constant
// rate to 90 and 30 degrees, reached at t = 1 (neither carries five tips).
TEST(DevelopmentalModel, LateralsTurnFromTheMeanAngleToTheirOwn) {
  const TreeGraph t = two_laterals();
  const DevelopmentalModel m(t);
  const auto angle_of = [](const TreeGraph& s, NodeId n) {
    const Eigen::Vector3d d = s.direction(n);
    return std::atan2(std::abs(d.x()), d.z()) * 180.0 / kPi;
  };
  for (const double s : {0.8, 0.9, 0.95}) {
    const TreeGraph st = m.stage(s);
    // Stage node ids: main 0..3, then the first lateral's edges, then the second's.
    const double done_first = (s - 0.5) / 0.5, done_second = (s - 0.75) / 0.25;
    EXPECT_NEAR(angle_of(st, 4), 60.0 + 30.0 * done_first, 1e-9) << s;
    EXPECT_NEAR(angle_of(st, 6), 60.0 - 30.0 * done_second, 1e-9) << s;
    // The lateral's second edge turns with its base.
    EXPECT_NEAR(angle_of(st, 5), angle_of(st, 4), 1e-9) << s;
  }
}

// Eq. 5.7-5.8 on a fork: b = (r1^u + r2^u) / r_p^u; before the lateral exists the parent carries
// only its apical tip (the mean tip radius while it is not a tip of the given tree).
TEST(DevelopmentalModel, RadiiFollowThePipeModelFromTheTips) {
  TreeGraph t;
  const NodeId root = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.2);
  const NodeId mid = edge(t, root, Eigen::Vector3d::UnitZ(), 1.0, 0.15);
  edge(t, mid, Eigen::Vector3d::UnitZ(), 1.0, 0.08);
  edge(t, root, at_angle(60), 1.0, 0.06);
  const DevelopmentalModel m(t);
  const double u = 2.5;
  const double b_root = (std::pow(0.15, u) + std::pow(0.06, u)) / std::pow(0.2, u);
  const double b_mid = std::pow(0.08, u) / std::pow(0.15, u);
  const double tip = (0.08 + 0.06) / 2.0;  // r_avg over the given tips
  // t = 0.55: main axis 1.65 long (edges root and mid, mid growing), lateral not started
  // (it starts when the main axis reaches 1, at t = 1/3, grows at 1 / (2/3) = 1.5: 0.325 long).
  const TreeGraph st = m.stage(0.55);
  ASSERT_EQ(st.size(), 3u);  // root, mid (growing), lateral (growing)
  // mid is a tip now, not in the given tree: r_avg. The lateral is a given tip: its own radius.
  EXPECT_NEAR(st.radius(1), tip, 1e-12);
  EXPECT_NEAR(st.radius(2), 0.06, 1e-12);
  EXPECT_NEAR(st.radius(0), std::pow((std::pow(tip, u) + std::pow(0.06, u)) / b_root, 1.0 / u),
              1e-12);
  const TreeGraph late = m.stage(0.9);
  ASSERT_EQ(late.size(), 4u);
  EXPECT_NEAR(late.radius(1), std::pow(std::pow(0.08, u) / b_mid, 1.0 / u), 1e-12);
}

// The root of eq. 5.8 to double precision at every scale of radius (millimetre twigs to a
// giant's trunk, and beyond float's range), for the default u and for another.
TEST(DevelopmentalModel, PipeModelRootHoldsAtEveryScale) {
  for (const double u : {2.5, 2.0, 3.0}) {
    for (const double scale : {1e-14, 1e-4, 1e-2, 1.0, 3.7, 1e3, 1e14}) {
      TreeGraph t;
      const NodeId root = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.2 * scale);
      const NodeId mid = edge(t, root, Eigen::Vector3d::UnitZ(), 1.0, 0.15 * scale);
      edge(t, mid, Eigen::Vector3d::UnitZ(), 1.0, 0.08 * scale);
      edge(t, root, at_angle(60), 1.0, 0.06 * scale);
      StagesParams params;
      params.pipe_exponent = u;
      const DevelopmentalModel m(t, params);
      const double b_root = (std::pow(0.15, u) + std::pow(0.06, u)) / std::pow(0.2, u);
      const double tip = (0.08 + 0.06) / 2.0;
      const double expected =
          scale * std::pow((std::pow(tip, u) + std::pow(0.06, u)) / b_root, 1.0 / u);
      const TreeGraph st = m.stage(0.55);
      EXPECT_NEAR(st.radius(0) / expected, 1.0, 1e-13) << "u " << u << " scale " << scale;
    }
  }
}

TEST(DevelopmentalModel, ChildrenAlikeWithinFivePercentKeepTheLevel) {
  TreeGraph t;
  const NodeId root = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.2);
  edge(t, root, at_angle(20), 1.0, 0.1);
  edge(t, root, at_angle(-20.5), 1.0, 0.102);
  const DevelopmentalModel m(t);
  EXPECT_EQ(m.level()[1], 1);
  EXPECT_EQ(m.level()[2], 1);
  TreeGraph u = t;
  u.set_radius(1, 0.05);  // one child half as thick: a lateral of level 2
  EXPECT_EQ(DevelopmentalModel(u).level()[1], 2);
  EXPECT_EQ(DevelopmentalModel(u).level()[2], 1);
}

// The trunk after a bend: the straighter child is a thin lateral. Pirk's rule follows the
// lateral, the default follows the thick trunk.
TEST(DevelopmentalModel, TheThickChildContinuesTheAxisUnlessPirksRuleIsAsked) {
  TreeGraph t;
  const NodeId root = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.2);
  edge(t, root, at_angle(35), 1.0, 0.15);   // the trunk, bent
  edge(t, root, at_angle(-10), 1.0, 0.03);  // a thin, straighter lateral
  const DevelopmentalModel thickest(t);
  EXPECT_EQ(thickest.chain()[1], 0u);
  EXPECT_EQ(thickest.level()[2], 2);
  StagesParams pirk;
  pirk.continuation = Continuation::kLeastDeviation;
  const DevelopmentalModel least(t, pirk);
  EXPECT_EQ(least.chain()[2], 0u);
  EXPECT_EQ(least.level()[1], 2);
}

TEST(DevelopmentalModel, OrgansAppearWithTheirCompleteEdge) {
  TreeGraph t;
  const NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  const NodeId b = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  NodeData leaf;
  leaf.kind = OrganKind::kLeaf;
  leaf.start = t.end(b);
  leaf.end = t.end(b) + Eigen::Vector3d(0.1, 0.0, 0.0);
  leaf.radius = 0.05;
  t.add_node(b, leaf);
  const DevelopmentalModel m(t);
  EXPECT_EQ(m.stage(0.9).size(), 2u);
  EXPECT_EQ(m.stage(1.0).size(), 3u);
  EXPECT_THROW(DevelopmentalModel(TreeGraph{}), ValueError);
}

// Pirk 5.3.7: until the chain's tip is complete, the growing tip carries the tip's leaves.
TEST(DevelopmentalModel, GrowingTipsCarryTheLeavesOfTheirChainsTip) {
  TreeGraph t;
  NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  NodeData leaf;
  leaf.kind = OrganKind::kLeaf;
  leaf.start = t.end(a) + Eigen::Vector3d(0.0, 0.0, 0.01);
  leaf.end = leaf.start + Eigen::Vector3d(0.1, 0.0, 0.0);
  leaf.radius = 0.05;
  t.add_node(a, leaf);
  const DevelopmentalModel m(t);
  const TreeGraph st = m.stage(0.5);  // edge 0 complete, edge 1 half grown: the tip
  ASSERT_EQ(st.size(), 3u);
  EXPECT_EQ(st.kind(2), OrganKind::kLeaf);
  EXPECT_EQ(st.parent(2), 1u);
  EXPECT_LT((st.start(2) - (st.end(1) + Eigen::Vector3d(0.0, 0.0, 0.01))).norm(), 1e-12);
  EXPECT_LT((st.end(2) - st.start(2) - Eigen::Vector3d(0.1, 0.0, 0.0)).norm(), 1e-12);
  EXPECT_EQ(m.stage(1.0).size(), 4u);  // at the end only the given leaf
}

// Eq. 5.11: t_new = sin((t n - s) 2 pi) / (2 pi n c) + t; with c = 1 growth stops once a season.
TEST(DevelopmentalModel, SeasonalRemappingOfEquation511) {
  EXPECT_DOUBLE_EQ(seasonal_time(0.0, 4, 1.0, 0.0), 0.0);
  EXPECT_NEAR(seasonal_time(1.0, 4, 1.0, 0.0), 1.0, 1e-15);
  EXPECT_NEAR(seasonal_time(0.0625, 4, 1.2, 0.0), 1.0 / (2 * kPi * 4 * 1.2) + 0.0625, 1e-15);
  double previous = -1.0;
  for (int k = 0; k <= 1000; ++k) {
    const double v = seasonal_time(k / 1000.0, 3, 1.0, 0.5);
    EXPECT_GE(v, previous - 1e-15);  // f'(t) = 1 + cos(...) / c >= 0 for c >= 1
    previous = v;
  }
  EXPECT_THROW(seasonal_time(0.5, 0), ValueError);
}

}  // namespace
}  // namespace fspm::stages
