// Added structures (Pirk 5.3.5-5.3.6) on a hand-built tree whose crown ratio, copy positions and
// removal times follow in closed form from eq. 5.10.
#include "stages/added_structures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fspm/error.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::stages {
namespace {

NodeId edge(TreeGraph& t, NodeId parent, const Eigen::Vector3d& dir, double length, double r) {
  NodeData d;
  d.start = parent == kNoNode ? Eigen::Vector3d::Zero() : t.end(parent);
  d.direction = dir.normalized();
  d.end = d.start + length * d.direction;
  d.length = length;
  d.radius = r;
  return t.add_node(parent, d);
}

// A vertical trunk of eight unit edges (ends at z = 1..8) with one horizontal lateral of length 1
// at the ends of edges 3..6 (z = 4..7): height 8, crown base 4, crown ratio 0.5; the trunk below
// z = 4 is bare.
TreeGraph bare_trunk() {
  TreeGraph t;
  NodeId a = kNoNode;
  std::vector<NodeId> trunk;
  for (int k = 0; k < 8; ++k) trunk.push_back(a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1));
  for (int k = 3; k <= 6; ++k) {
    edge(t, trunk[k], Eigen::Vector3d(k % 2 ? 1.0 : -1.0, 0.0, 0.0), 1.0, 0.05);
  }
  return t;
}

StagesParams with_added() {
  StagesParams p;
  p.added.enabled = true;
  return p;
}

// Eq. 5.10 by hand: c0 = ln(0.99 / 0.01) = ln 99, c1 = (logit(0.5) - ln 99) / 8 = -ln(99) / 8, so
// CR(h) = 1 / (1 + 99^(h / 8 - 1)); the crown base of a tree of height h is h (1 - CR(h)).
double hand_crown_base(double h) { return h * (1.0 - 1.0 / (1.0 + std::pow(99.0, h / 8.0 - 1.0))); }

// Laterals whose base is below the given crown base (z < 4): only copies can be there.
int branches_below_crown(const TreeGraph& st) {
  int count = 0;
  for (NodeId i = 1; i < st.size(); ++i) {
    const bool lateral = st.kind(i) == OrganKind::kInternode && std::abs(st.direction(i).z()) < 0.5;
    if (lateral && st.start(i).z() < 4.0 - 1e-9) ++count;
  }
  return count;
}

TEST(AddedStructures, CrownRatioOfTheGivenTree) {
  const TreeGraph t = bare_trunk();
  const DevelopmentalModel m(t, with_added());
  EXPECT_NEAR(m.crown().height_m, 8.0, 1e-12);
  EXPECT_NEAR(m.crown().crown_base_m, 4.0, 1e-12);
  EXPECT_NEAR(m.crown().crown_ratio(), 0.5, 1e-12);
  EXPECT_NEAR(m.crown_ratio_curve().c0(), std::log(99.0), 1e-12);
  EXPECT_NEAR(m.crown_ratio_curve().c1(), -std::log(99.0) / 8.0, 1e-12);
  EXPECT_NEAR(m.crown_ratio_curve().crown_ratio(0.0), 0.99, 1e-12);
  EXPECT_NEAR(m.crown_ratio_curve().crown_ratio(8.0), 0.5, 1e-12);
}

// The bare trunk from the end of the root edge (arc 1) to the crown base (arc 4) is 3 long; the
// crown's laterals at arcs 4, 5, 6 move down by 3 to arcs 1, 2, 3 (one copy block covers it).
TEST(AddedStructures, CopiesOfTheLowestCrownBlockFillTheBareTrunk) {
  const TreeGraph t = bare_trunk();
  const DevelopmentalModel m(t, with_added());
  EXPECT_EQ(m.added_branch_count(), 3u);
  const TreeGraph st = m.stage(0.5);  // all three present (see below)
  std::vector<double> heights;
  for (NodeId i = 1; i < st.size(); ++i) {
    if (std::abs(st.direction(i).z()) < 0.5 && st.start(i).z() < 4.0) {
      heights.push_back(st.start(i).z());
    }
  }
  std::sort(heights.begin(), heights.end());
  ASSERT_EQ(heights.size(), 3u);
  EXPECT_NEAR(heights[0], 1.0, 1e-12);
  EXPECT_NEAR(heights[1], 2.0, 1e-12);
  EXPECT_NEAR(heights[2], 3.0, 1e-12);
}

// The trunk grows at 8 per unit of t (eq. 5.4) and is the top of every stage, so h(t) = 8 t. A
// copy at height z is present once the trunk is past it (8 t > z) and while z >= the crown base
// of eq. 5.10 at h(t).
TEST(AddedStructures, CopiesAreShedAsTheCrownRatioFalls) {
  const TreeGraph t = bare_trunk();
  const DevelopmentalModel m(t, with_added());
  for (const double time : {0.1, 0.2, 0.3, 0.5, 0.7, 0.75, 0.8, 0.9, 0.95, 0.99}) {
    const double h = 8.0 * time;
    int expected = 0;
    for (const double z : {1.0, 2.0, 3.0}) expected += h > z && z >= hand_crown_base(h) ? 1 : 0;
    EXPECT_EQ(branches_below_crown(m.stage(time)), expected) << "t = " << time;
  }
  // Spot values: at t = 0.5 the crown base is 0.37 (all three), at 0.75 it is 1.44, at 0.9 2.79.
  EXPECT_EQ(branches_below_crown(m.stage(0.5)), 3);
  EXPECT_EQ(branches_below_crown(m.stage(0.75)), 2);
  EXPECT_EQ(branches_below_crown(m.stage(0.9)), 1);
}

TEST(AddedStructures, TheLastStageIsTheGivenTree) {
  const TreeGraph t = bare_trunk();
  const TreeGraph st = DevelopmentalModel(t, with_added()).stage(1.0);
  ASSERT_EQ(st.size(), t.size());
  for (NodeId i = 0; i < t.size(); ++i) {
    EXPECT_EQ(st.parent(i), t.parent(i)) << i;
    EXPECT_LT((st.start(i) - t.start(i)).norm(), 1e-12) << i;
    EXPECT_LT((st.end(i) - t.end(i)).norm(), 1e-12) << i;
    EXPECT_NEAR(st.radius(i), t.radius(i), 1e-12) << i;
  }
}

// Pirk 5.3.6: shed branches still count in eq. 5.8, so the trunk below a shed copy is as thick
// as when the copy is there: the stage radii of the given nodes do not depend on shedding.
TEST(AddedStructures, ShedBranchesStillCountInTheRadii) {
  const TreeGraph t = bare_trunk();
  StagesParams keep = with_added();
  keep.added.gamma = 1e-6;  // CR about 1 at every height: nothing is shed before t = 1
  const TreeGraph shed = DevelopmentalModel(t, with_added()).stage(0.9);
  const TreeGraph kept = DevelopmentalModel(t, keep).stage(0.9);
  EXPECT_EQ(branches_below_crown(kept), 3);
  EXPECT_EQ(branches_below_crown(shed), 1);
  EXPECT_NEAR(shed.radius(0), kept.radius(0), 1e-12);
}

TEST(AddedStructures, SameTreeSameStages) {
  const TreeGraph t = bare_trunk();
  const DevelopmentalModel a(t, with_added()), b(t, with_added());
  for (const double time : {0.3, 0.6, 0.85}) EXPECT_TRUE(a.stage(time).identical(b.stage(time)));
}

// Forestry's crown base is the lowest live branch: in a tree with leaves, a leafless stub below
// the crown does not lower it.
TEST(AddedStructures, TheCrownStartsAtTheLowestLiveBranch) {
  TreeGraph t = bare_trunk();
  const std::size_t given = t.size();
  for (NodeId i = 0; i < given; ++i) {
    if (t.parent(i) == kNoNode || std::abs(t.direction(i).z()) > 0.5) continue;
    NodeData leaf = t.data(i);
    leaf.kind = OrganKind::kLeaf;
    leaf.start = leaf.end = t.end(i);
    leaf.length = 0.1;
    t.add_node(i, leaf);
  }
  edge(t, 1, Eigen::Vector3d::UnitY(), 0.3, 0.01);  // a dead stub at z = 2
  const DevelopmentalModel m(t, with_added());
  EXPECT_NEAR(m.crown().crown_base_m, 4.0, 1e-12);
  EXPECT_NEAR(m.crown().crown_ratio(), 0.5, 1e-12);
  EXPECT_EQ(m.added_branch_count(), 3u);
}

TEST(AddedStructures, OffByDefaultAndNothingToAddWithoutABareTrunk) {
  const TreeGraph t = bare_trunk();
  EXPECT_EQ(DevelopmentalModel(t).added_branch_count(), 0u);
  EXPECT_NEAR(DevelopmentalModel(t).crown().crown_ratio(), 0.5, 1e-12);
  TreeGraph full;  // laterals from the end of the root edge on: nothing bare above it
  NodeId a = edge(full, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  edge(full, a, Eigen::Vector3d::UnitX(), 1.0, 0.05);
  a = edge(full, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1);
  EXPECT_EQ(DevelopmentalModel(full, with_added()).added_branch_count(), 0u);
}

// Copies twice the size of the laterals (radius 0.1) are as thick as the trunk (0.1) and would
// continue the main chain; none is added.
TEST(AddedStructures, NoCopyAsThickAsTheTrunk) {
  StagesParams p = with_added();
  p.added.scale = 2.0;
  const DevelopmentalModel m(bare_trunk(), p);
  EXPECT_EQ(m.added_branch_count(), 0u);
  p.added.scale = 1.7;  // radius 0.085 < 0.9 x 0.1
  EXPECT_EQ(DevelopmentalModel(bare_trunk(), p).added_branch_count(), 3u);
}

TEST(AddedStructures, BadParametersAreRejected) {
  StagesParams p = with_added();
  p.added.crown_ratio_at_zero_height = 1.0;
  EXPECT_THROW(DevelopmentalModel(bare_trunk(), p), ValueError);
  p = with_added();
  p.added.scale = 0.0;
  EXPECT_THROW(DevelopmentalModel(bare_trunk(), p), ValueError);
}

}  // namespace
}  // namespace fspm::stages
