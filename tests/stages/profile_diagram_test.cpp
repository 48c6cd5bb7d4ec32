// Profile diagrams (Pirk 5.3.4) of a hand-built tree, by stratified clipping and by main-axis
// cutting, against layer sums worked out by hand.
#include "stages/profile_diagram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::stages {
namespace {

constexpr double kPi = std::numbers::pi;

NodeId add(TreeGraph& t, NodeId parent, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
           double r, OrganKind kind = OrganKind::kInternode) {
  NodeData d;
  d.start = from;
  d.end = to;
  d.radius = r;
  d.kind = kind;
  if (kind != OrganKind::kInternode) {
    d.direction = Eigen::Vector3d::UnitX();
    d.length = 0.1;
  }
  return t.add_node(parent, d);
}

// A vertical trunk of three unit edges of unit volume (pi r^2 = 1) from z = 0 to 3; a lateral
// from the end of the first (z = 1) to (1, 0, 3) of volume 1 (length sqrt 5); one leaf at the
// lateral's end (z = 3) and one on the trunk at z = 2.
TreeGraph tilted_lateral() {
  TreeGraph t;
  const double r_trunk = 1.0 / std::sqrt(kPi);
  const double r_lateral = std::sqrt(1.0 / (kPi * std::sqrt(5.0)));
  const NodeId a = add(t, kNoNode, {0, 0, 0}, {0, 0, 1}, r_trunk);
  const NodeId b = add(t, a, {0, 0, 1}, {0, 0, 2}, r_trunk);
  add(t, b, {0, 0, 2}, {0, 0, 3}, r_trunk);
  const NodeId l = add(t, a, {0, 0, 1}, {1, 0, 3}, r_lateral);
  add(t, l, {1, 0, 3}, {1, 0, 3}, 0.0, OrganKind::kLeaf);
  add(t, b, {0, 0, 2}, {0, 0, 2}, 0.0, OrganKind::kLeaf);
  return t;
}

void expect_near(const std::vector<double>& got, const std::vector<double>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) EXPECT_NEAR(got[k], want[k], 1e-12) << k;
}

// STC: the lateral's volume 1 is split over z 1..3, half in layer 1 and half in layer 2; its
// leaf at z = 3 is in the top layer. Shares from the top: leaves 2/2, 2/2, 2/2; wood 1.5/4,
// 3/4, 4/4; T is their mean.
TEST(ProfileDiagram, StratifiedClippingCountsWhatLiesInTheLayer) {
  const TreeGraph t = tilted_lateral();
  const ProfileDiagram p =
      profile_diagram(t, DevelopmentalModel(t).chain(), 1.0, Clipping::kStratified);
  expect_near(p.wood_m3, {1.0, 1.5, 1.5});
  expect_near(p.leaves, {0.0, 0.0, 2.0});
  expect_near(p.leaves_above, {1.0, 1.0, 1.0});
  expect_near(p.tissue_above, {1.0, (1.0 + 0.75) / 2, (1.0 + 0.375) / 2});
}

// MAC: the whole lateral and its leaf count where it leaves the axis, at z = 1 (layer 1); the
// trunk's leaf stays at z = 2. Wood shares from the top 1/4, 3/4, 1; leaves 1/2, 1, 1.
TEST(ProfileDiagram, MainAxisCuttingCountsWhatEmergesFromTheSegment) {
  const TreeGraph t = tilted_lateral();
  const ProfileDiagram p =
      profile_diagram(t, DevelopmentalModel(t).chain(), 1.0, Clipping::kMainAxis);
  expect_near(p.wood_m3, {1.0, 2.0, 1.0});
  expect_near(p.leaves, {0.0, 1.0, 1.0});
  expect_near(p.leaves_above, {1.0, 1.0, 0.5});
  expect_near(p.tissue_above, {1.0, (1.0 + 0.75) / 2, (0.5 + 0.25) / 2});
}

// Half-metre layers: the trunk's unit edges split in two, the lateral's volume in four quarters.
TEST(ProfileDiagram, ThinnerLayersSplitTheSegments) {
  const TreeGraph t = tilted_lateral();
  const ProfileDiagram p =
      profile_diagram(t, DevelopmentalModel(t).chain(), 0.5, Clipping::kStratified);
  expect_near(p.wood_m3, {0.5, 0.5, 0.75, 0.75, 0.75, 0.75});
}

TEST(ProfileDiagram, BadLayerOrChainsAreRejected) {
  const TreeGraph t = tilted_lateral();
  const auto chain = DevelopmentalModel(t).chain();
  EXPECT_THROW(profile_diagram(t, chain, 0.0, Clipping::kStratified), ValueError);
  EXPECT_THROW(profile_diagram(t, {0, 0}, 1.0, Clipping::kMainAxis), ValueError);
  EXPECT_EQ(clipping_name(Clipping::kMainAxis), "main_axis");
}

}  // namespace
}  // namespace fspm::stages
