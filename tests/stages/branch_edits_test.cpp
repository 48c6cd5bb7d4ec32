// Growth-based editing of selected branches (Pirk 5.4.1) on a hand-built tree whose growth times
// follow from eq. 5.3-5.4 by hand.
#include "stages/branch_edits.hpp"

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

// A trunk of four unit edges (radius 0.05): nodes 0 and 1 vertical, 2 and 3 leaning to -x at
// 45 degrees; on the end of node 0 (z = 1) a lateral of two unit edges along +x (nodes 4, 5,
// radius 0.02). By eq. 5.3-5.4: the trunk grows at 4 per unit of t, so node 0 is complete at
// t = 0.25 and the end of node 2 is reached at t = 0.75; the lateral starts at 0.25 and grows at
// 2 / 0.75 = 8/3, so its length at t is clamp(8/3 (t - 0.25), 0, 2).
TreeGraph leaning_trunk() {
  TreeGraph t;
  const NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.05);
  const NodeId b = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.05);
  const NodeId c = edge(t, b, Eigen::Vector3d(-1.0, 0.0, 1.0), 1.0, 0.05);
  edge(t, c, Eigen::Vector3d(-1.0, 0.0, 1.0), 1.0, 0.05);
  const NodeId l = edge(t, a, Eigen::Vector3d::UnitX(), 1.0, 0.02);
  edge(t, l, Eigen::Vector3d::UnitX(), 1.0, 0.02);
  return t;
}

double lateral_length(double t) { return std::clamp(8.0 / 3.0 * (t - 0.25), 0.0, 2.0); }

// Total length of the internodes of `st` in the subtree of the child of the node ending at
// `at` whose heading is `dir` (0 when there is none).
double branch_length_at(const TreeGraph& st, const Eigen::Vector3d& at,
                        const Eigen::Vector3d& dir) {
  std::vector<std::uint8_t> in(st.size(), 0);
  double sum = 0.0;
  for (NodeId i = 1; i < st.size(); ++i) {
    const NodeId p = st.parent(i);
    const bool root = (st.start(i) - at).norm() < 1e-9 && (st.direction(i) - dir).norm() < 1e-9 &&
                      (st.end(p) - at).norm() < 1e-9 && !in[p];
    in[i] = st.kind(i) == OrganKind::kInternode && (root || in[p]);
    if (in[i]) sum += st.length(i);
  }
  return sum;
}

StagesParams aged(double delta) {
  StagesParams p;
  p.edits.age.push_back({5, delta});  // node 5 lies on the lateral chain based at node 4
  return p;
}

// A branch made older by k steps of 1/20 shows at each stage what it showed k stages later, once
// its branch point exists (t >= 0.25); made younger, it appears k stages later and is short of
// its given length at t = 1.
TEST(BranchEdits, AgeShiftsTheBranchByWholeStages) {
  const TreeGraph t = leaning_trunk();
  const DevelopmentalModel older(t, aged(0.15)), younger(t, aged(-0.15)), plain(t);
  const Eigen::Vector3d base(0, 0, 1), x = Eigen::Vector3d::UnitX();
  int first_plain = 0, first_younger = 0;
  for (int s = 1; s <= 20; ++s) {
    const double time = s / 20.0;
    const double l_old = branch_length_at(older.stage(time), base, x);
    const double l_young = branch_length_at(younger.stage(time), base, x);
    const double l_plain = branch_length_at(plain.stage(time), base, x);
    EXPECT_NEAR(l_plain, lateral_length(time), 1e-9) << "t = " << time;
    if (time >= 0.25) {
      EXPECT_NEAR(l_old, lateral_length(std::min(time + 0.15, 1.0)), 1e-9) << "t = " << time;
    }
    EXPECT_NEAR(l_young, lateral_length(time - 0.15), 1e-9) << "t = " << time;
    if (!first_plain && l_plain > 0.0) first_plain = s;
    if (!first_younger && l_young > 0.0) first_younger = s;
  }
  EXPECT_EQ(first_plain, 6);                  // t = 0.30
  EXPECT_EQ(first_younger, first_plain + 3);  // three stages later
  EXPECT_NEAR(branch_length_at(younger.stage(1.0), base, x), 1.6, 1e-9);
  // Radii at t = 1 (eq. 5.8): the younger branch's growing tip is a tip of the given tree and
  // keeps its own radius 0.02, its first edge (b = 1) has 0.02 too, and the trunk's root edge
  // ((0.05^u + 0.02^u) / b)^(1/u) = 0.05 with b = (0.05^u + 0.02^u) / 0.05^u: as given, though
  // not taken as complete.
  const TreeGraph y1 = younger.stage(1.0);
  EXPECT_EQ(y1.radius(5), 0.02);
  EXPECT_NEAR(y1.radius(4), 0.02, 1e-12);
  EXPECT_NEAR(y1.radius(0), 0.05, 1e-12);
  EXPECT_NEAR(older.stage(1.0).radius(0), t.radius(0), 1e-12);
  EXPECT_EQ(y1.radius(3), t.radius(3));
}

// The lateral copied onto the end of node 2 (leaning 45 degrees to -x): turned by the rotation
// taking +z to (-1, 0, 1) / sqrt 2, its heading +x becomes (1, 0, 1) / sqrt 2, and it stands at
// the end of node 2, (-sqrt 0.5, 0, 2 + sqrt 0.5). It starts when the trunk gets there
// (t = 0.75) at the age the source had at its start, so its length at t is that of the source at
// t - 0.5: 8/3 (t - 0.75), 2/3 at t = 1.
TEST(BranchEdits, CopiedBranchStandsRigidlyAtTheTargetAndGrowsWithTime) {
  const TreeGraph t = leaning_trunk();
  StagesParams p;
  p.edits.copy.push_back({4, 2});
  const DevelopmentalModel m(t, p);
  const double h = std::sqrt(0.5);
  const Eigen::Vector3d at(-h, 0.0, 2.0 + h), dir(h, 0.0, h);
  int first = 0;
  for (int s = 1; s <= 20; ++s) {
    const double time = s / 20.0;
    const TreeGraph st = m.stage(time);
    const double l = branch_length_at(st, at, dir);
    EXPECT_NEAR(l, lateral_length(time - 0.5), 1e-9) << "t = " << time;
    if (!first && l > 0.0) first = s;
    // The source is as without the edit.
    EXPECT_NEAR(branch_length_at(st, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitX()),
                lateral_length(time), 1e-9);
  }
  EXPECT_EQ(first, 16);  // t = 0.80, the first stage after 0.75
  const TreeGraph last = m.stage(1.0);
  EXPECT_NEAR(branch_length_at(last, at, dir), 2.0 / 3.0, 1e-9);
  EXPECT_EQ(last.size(), t.size() + 1);  // the copy's first edge only: 2/3 of it grown
  // Its parent carries one more pipe (eq. 5.8, b = 1): the copy's growing tip has r_avg = 0.035,
  // so node 2 has (0.05^u + 0.035^u)^(1/u); the trunk's tip above is as given.
  const double u = 2.5;
  EXPECT_NEAR(last.radius(6), 0.035, 1e-12);
  EXPECT_NEAR(last.radius(2), std::pow(std::pow(0.05, u) + std::pow(0.035, u), 1.0 / u), 1e-12);
  EXPECT_EQ(last.radius(3), t.radius(3));
}

TEST(BranchEdits, EditsOfTheMainAxisOrMissingNodesAreRejected) {
  const TreeGraph t = leaning_trunk();
  StagesParams p;
  p.edits.age.push_back({1, 0.1});  // the trunk
  EXPECT_THROW(DevelopmentalModel(t, p), ValueError);
  p.edits.age = {{4, 2.0}};  // more than the whole development
  EXPECT_THROW(DevelopmentalModel(t, p), ValueError);
  p.edits.age.clear();
  p.edits.copy.push_back({4, 99});
  EXPECT_THROW(DevelopmentalModel(t, p), ValueError);
  p.edits.copy = {{99, 2}};
  EXPECT_THROW(DevelopmentalModel(t, p), ValueError);
}

TEST(BranchEdits, NoEditsNoChange) {
  const TreeGraph t = leaning_trunk();
  StagesParams p;
  p.edits.age.push_back({4, 0.0});
  const DevelopmentalModel edited(t, p), plain(t);
  for (const double time : {0.3, 0.6, 1.0}) {
    EXPECT_TRUE(edited.stage(time).identical(plain.stage(time))) << "t = " << time;
  }
}

}  // namespace
}  // namespace fspm::stages
