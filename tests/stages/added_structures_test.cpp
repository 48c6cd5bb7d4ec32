// Added structures (Pirk 5.3.5-5.3.6) on a hand-built tree whose crown ratio, copy positions and
// removal times follow in closed form from eq. 5.10.
#include "stages/added_structures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "fspm/error.hpp"
#include "stages/developmental_model.hpp"
#include "tests/stages/edge_builder.hpp"

namespace fspm::stages {
namespace {

using testing::edge;

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

// Pirk 5.3.5, overlap regions. A vertical trunk of ten unit edges (radius 0.1, ends at
// z = 1..10); on the end of edge 3 (z = 4) a lateral rising at 45 degrees to z = 6 (length
// 2 sqrt 2, radius 0.08), on z = 5..9 horizontal unit laterals (radius 0.05). Crown base 4,
// height 10; the bare trunk from z = 1 to 4 is filled, so the overlap region is z in [4, 7), and
// the copy period is 3 (the bare length; the crown block is 6): the laterals at z = 7, 8, 9 are
// the candidates for z = 4, 5, 6.
TreeGraph rising_lateral_tree() {
  TreeGraph t;
  NodeId a = kNoNode;
  std::vector<NodeId> trunk;
  for (int k = 0; k < 10; ++k) trunk.push_back(a = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.1));
  edge(t, trunk[3], Eigen::Vector3d(1.0, 0.0, 1.0), 2.0 * std::sqrt(2.0), 0.08);
  for (int k = 4; k <= 8; ++k) {
    edge(t, trunk[k], Eigen::Vector3d(k % 2 ? 1.0 : -1.0, 0.0, 0.0), 1.0, 0.05);
  }
  return t;
}

StagesParams with_overlap() {
  StagesParams p = with_added();
  p.added.overlap = true;
  p.added.overlap_layer_m = 1.0;
  return p;
}

// Laterals (internodes leaving the trunk) whose base is at height z.
int laterals_at(const TreeGraph& st, double z) {
  int count = 0;
  for (NodeId i = 1; i < st.size(); ++i) {
    const NodeId p = st.parent(i);
    const bool on_trunk = st.kind(p) == OrganKind::kInternode && st.direction(p).z() > 0.999;
    const bool lateral = st.kind(i) == OrganKind::kInternode && st.direction(i).z() < 0.999;
    if (on_trunk && lateral && std::abs(st.start(i).z() - z) < 1e-9) ++count;
  }
  return count;
}

// The heuristic by hand, with layers of 1 m and no leaves (T = half the wood share above). Wood
// pi r^2 l: trunk 10 x 0.01, horizontals 5 x 0.0025, the rising one 0.0064 * 2 sqrt 2, of which
// stratified clipping puts half in layer 5 ([5, 6)) and main-axis cutting all in layer 4. The
// shares above differ only in layer 5: MAC 0.0625 / W, STC (0.0625 + 0.0032 sqrt 8) / W, a ratio
// of 1.145 > 1.1; layers 4 and 6 have a ratio of 1 and T well above 0.05. So of the three
// candidates only the one on z = 5 is kept.
TEST(AddedStructures, OverlapRegionIsFilledWhereStratifiedClippingExceedsMainAxisCutting) {
  const double w = 10 * 0.01 + 5 * 0.0025 + 0.0064 * std::sqrt(8.0);
  const double mac5 = 0.5 * (5 * 0.01 + 5 * 0.0025) / w;
  const double stc5 = 0.5 * (5 * 0.01 + 5 * 0.0025 + 0.0032 * std::sqrt(8.0)) / w;
  ASSERT_GT(stc5, 1.1 * mac5);  // the hand figures put layer 5 in the region kept
  const TreeGraph t = rising_lateral_tree();
  const DevelopmentalModel m(t, with_overlap());
  EXPECT_EQ(m.overlap_branch_count(), 1u);
  EXPECT_EQ(m.added_branch_count(), 4u);  // three below the crown (z = 1, 2, 3) and one
  EXPECT_NEAR(m.overlap_top_m(), 7.0, 1e-12);
  // At t = 0.55 the trunk is 5.5 high and every copy present (checked below by eq. 5.10).
  const TreeGraph st = m.stage(0.55);
  EXPECT_EQ(laterals_at(st, 4.0), 1);  // the given rising lateral only
  EXPECT_EQ(laterals_at(st, 5.0), 2);  // the given one and the copy of the lateral at z = 8
  EXPECT_EQ(laterals_at(st, 6.0), 0);  // not grown yet; its lateral starts at t = 0.6
  const TreeGraph plain = DevelopmentalModel(t, with_added()).stage(0.55);
  EXPECT_EQ(laterals_at(plain, 5.0), 1);         // without overlap regions
  EXPECT_EQ(laterals_at(m.stage(0.8), 6.0), 1);  // the copy for z = 6 was not made
}

// Removal (5.3.6): eq. 5.10 through CR(0) = 0.99 and the crown ratio (10 - 7) / 10 = 0.3 whose base
// is the overlap region's top; the copy at z = 5 is present while 5 >= h (1 - CR(h)).
TEST(AddedStructures, OverlapCopiesAreShedByTheirOwnCrownRatioCurve) {
  const TreeGraph t = rising_lateral_tree();
  const DevelopmentalModel m(t, with_overlap());
  const double c0 = std::log(99.0), c1 = (std::log(0.3 / 0.7) - c0) / 10.0;
  int present_seen = 0, shed_seen = 0;
  for (int step = 11; step <= 20; ++step) {
    const double time = step / 20.0;
    const TreeGraph st = m.stage(time);
    double h = 0.0;
    for (NodeId i = 0; i < st.size(); ++i) h = std::max(h, st.end(i).z());
    const double base = h * (1.0 - 1.0 / (1.0 + std::exp(-(c0 + c1 * h))));
    const int expected = time < 1.0 && 5.0 >= base ? 2 : 1;
    EXPECT_EQ(laterals_at(st, 5.0), expected) << "t = " << time << ", crown base " << base;
    (expected == 2 ? present_seen : shed_seen) += 1;
  }
  EXPECT_GT(present_seen, 0);
  EXPECT_GT(shed_seen, 1);  // shed before t = 1 too
  EXPECT_TRUE(m.stage(1.0).identical(DevelopmentalModel(t).stage(1.0)));
}

}  // namespace
}  // namespace fspm::stages
