// Branches shed before the given tree, from the pipe model (Shinozaki et al. 1964), on a
// hand-built tree whose pipes, growth times and shedding follow by hand.
#include "stages/shed_branches.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "stages/developmental_model.hpp"
#include "tests/stages/edge_builder.hpp"

namespace fspm::stages {
namespace {

using testing::edge;

constexpr double kTip = 0.01;  // the radius of every tip

double pipe_radius(double pipes) { return kTip * std::pow(pipes, 1.0 / 2.5); }

// A vertical trunk of four unit edges (nodes 0-3) with a lateral of two unit edges along +x at the
// end of node 2 (nodes 4, 5). Radii by the pipe model from tips of kTip (node 2 carries two
// pipes), except node 0, which holds one pipe more than node 1 needs: a shed branch of one tip.
TreeGraph trunk_with_disused_pipe() {
  TreeGraph t;
  const NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, pipe_radius(3.0));
  const NodeId b = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, pipe_radius(2.0));
  const NodeId c = edge(t, b, Eigen::Vector3d::UnitZ(), 1.0, pipe_radius(2.0));
  edge(t, c, Eigen::Vector3d::UnitZ(), 1.0, kTip);
  const NodeId l = edge(t, c, Eigen::Vector3d::UnitX(), 1.0, kTip);
  edge(t, l, Eigen::Vector3d::UnitX(), 1.0, kTip);
  return t;
}

std::size_t internodes(const TreeGraph& t) {
  std::size_t n = 0;
  for (NodeId i = 0; i < t.size(); ++i) n += t.kind(i) == OrganKind::kInternode;
  return n;
}

TEST(ShedBranches, SitesFromThePipeModel) {
  const std::vector<ShedSite> sites = find_shed_sites(trunk_with_disused_pipe(), 2.5, kTip, 0.5);
  ASSERT_EQ(sites.size(), 1u);
  EXPECT_EQ(sites[0].edge, 0u);
  EXPECT_NEAR(sites[0].pipes, 1.0, 1e-9);  // (3 - 2) tip pipes
  // A threshold above the excess finds nothing.
  EXPECT_TRUE(find_shed_sites(trunk_with_disused_pipe(), 2.5, kTip, 1.5).empty());
}

TEST(ShedBranches, SourceClosestInPipesThatStartsLater) {
  const std::vector<ShedSource> sources = {{10, 1.0, 0.9}, {11, 3.0, 0.2}, {12, 5.0, 0.7}};
  EXPECT_EQ(choose_shed_source(sources, 3.2, 0.1), 11u);   // closest, and it starts later
  EXPECT_EQ(choose_shed_source(sources, 3.2, 0.5), 12u);   // 11 starts earlier: 5 beats 1
  EXPECT_EQ(choose_shed_source(sources, 1.5, 0.5), 10u);   // 1 / 1.5 beats 5 / 1.5
  EXPECT_EQ(choose_shed_source(sources, 3.2, 0.95), 11u);  // none later: the closest
  EXPECT_EQ(choose_shed_source({}, 3.2, 0.1), kNoNode);
}

// The trunk grows at 4 per unit of t (eq. 5.3), so node 0's end is reached at 0.25 and node 2's
// at 0.75, where the lateral starts, growing at 2 / 0.25 = 8. The shed branch is a copy of the
// lateral (the only one, of one pipe) at the end of node 0, on a clock 0.75 - 0.25 = 0.5 ahead:
// 8 (t - 0.25) long from t = 0.25, complete, and shed, at t = 0.5.
TEST(ShedBranches, ACopyGrowsAndIsShedWhenComplete) {
  const TreeGraph given = trunk_with_disused_pipe();
  StagesParams p;
  p.shed.enabled = true;
  const DevelopmentalModel m(given, p);
  ASSERT_EQ(m.shed_branch_count(), 1u);
  EXPECT_NEAR(m.shed_times()[0], 0.5, 1e-12);
  const DevelopmentalModel plain(given);
  // t = 0.4: the trunk 1.6 long (nodes 0, 1), the copy 1.2 (both its edges).
  const TreeGraph young = m.stage(0.4);
  EXPECT_EQ(internodes(plain.stage(0.4)), 2u);
  ASSERT_EQ(internodes(young), 4u);
  double copy_length = 0.0;
  for (NodeId i = 0; i < young.size(); ++i) {
    if (young.direction(i).z() < 0.5) {
      copy_length += young.length(i);
      EXPECT_NEAR(young.start(i).z(), 1.0, 1e-12);  // at the end of node 0
    }
  }
  EXPECT_NEAR(copy_length, 1.2, 1e-12);
  // Its pipes stay in node 0 (eq. 5.8 with b of the given tree and the copy): node 0 is thicker
  // than the trunk above it would make it alone.
  EXPECT_GT(young.radius(0), plain.stage(0.4).radius(0));
  // Shed once complete; the last stage is the given tree.
  EXPECT_EQ(internodes(m.stage(0.5)), internodes(plain.stage(0.5)));
  const TreeGraph last = m.stage(1.0);
  ASSERT_EQ(last.size(), given.size());
  for (NodeId i = 0; i < given.size(); ++i) {
    EXPECT_NEAR(last.radius(i), given.radius(i), 1e-12 * given.radius(i) + 1e-15);
    EXPECT_NEAR((last.end(i) - given.end(i)).norm(), 0.0, 1e-12);
  }
}

TEST(ShedBranches, NothingOnATreeThatFollowsThePipeModel) {
  TreeGraph t = trunk_with_disused_pipe();
  t.set_radius(0, pipe_radius(2.0));
  StagesParams p;
  p.shed.enabled = true;
  EXPECT_EQ(DevelopmentalModel(t, p).shed_branch_count(), 0u);
}

}  // namespace
}  // namespace fspm::stages
