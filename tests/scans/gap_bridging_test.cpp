// Occlusion gaps bridged along the branch's direction (scans/directed_bridge.hpp): a branch whose
// far part lies beyond a 0.6 m gap, with a neighbouring limb passing nearer to that part than the
// branch's own near part.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>

#include <cmath>
#include <numbers>

#include "scans/encoder.hpp"
#include "scans/segment_distance.hpp"

namespace fspm::scans {
namespace {

// Points on the surface of the cylinder of radius r around a -> b, a ring of `around` points
// every `step_m`, leaving out the stretch between `gap_from` and `gap_to` (shares of the length).
void add_cylinder(PointSet& ps, const Eigen::Vector3d& a, const Eigen::Vector3d& b, double r,
                  double step_m, double gap_from = 2.0, double gap_to = 2.0) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  const double length = (b - a).norm();
  const int around = std::max(6, static_cast<int>(2.0 * std::numbers::pi * r / step_m));
  for (double s = 0.0; s <= length; s += step_m) {
    if (s / length > gap_from && s / length < gap_to) continue;
    for (int k = 0; k < around; ++k) {
      const double t = 2.0 * std::numbers::pi * k / around;
      ps.points.push_back(a + s * axis + r * (std::cos(t) * u + std::sin(t) * v));
    }
  }
}

TEST(GapBridging, AGapIsBridgedAlongTheBranchNotToTheNearerLimb) {
  PointSet ps;
  add_cylinder(ps, {0, 0, 0}, {0, 0, 4}, 0.1, 0.02);  // trunk
  // Branch A at 45 degrees from 2 m up, its points missing from 1.0 to 1.6 m along it.
  const Eigen::Vector3d a0(0, 0, 2), a1 = a0 + 2.83 * Eigen::Vector3d(1, 0, 1).normalized();
  add_cylinder(ps, a0, a1, 0.03, 0.01, 1.0 / 2.83, 1.6 / 2.83);
  // Limb B, horizontal at 3.2 m, passes 0.2 m from A's far part (A's near part: 0.6 m away).
  add_cylinder(ps, {0, 0, 3.2}, {2.0, 0.3, 3.2}, 0.03, 0.01);
  EncodeOptions o;
  o.root_diameter_m = 0.2;
  const EncodeResult r = encode_point_set(ps, o);
  ASSERT_EQ(r.gaps.size(), 1u);
  const Eigen::Vector3d dir = (a1 - a0).normalized();
  const Eigen::Vector3d near_end = a0 + 1.0 * dir, far_end = a0 + 1.6 * dir;
  // The bridge joins the two ends of the gap: 0.6 m along A, within the branch's radius.
  EXPECT_LT((r.gaps[0].from - far_end).norm(), 0.08);
  EXPECT_LT((r.gaps[0].to - near_end).norm(), 0.08);
  EXPECT_NEAR(r.gaps[0].length_m, 0.6, 0.08);
  // The skeleton runs through the gap, along the branch.
  const Eigen::Vector3d middle = 0.5 * (near_end + far_end);
  double nearest = 1e9;
  for (NodeId n = 0; n < r.full_skeleton.size(); ++n) {
    nearest = std::min(nearest, segment_distance(middle, middle, r.full_skeleton.start(n),
                                                 r.full_skeleton.end(n)));
  }
  EXPECT_LT(nearest, 0.1);
}

// The shortest edge, for comparison: without limb B the shortest edge is the one along the
// branch as well, and a piece too round to have an axis (a tuft) keeps its shortest edge.
TEST(GapBridging, ARoundPieceKeepsItsShortestEdge) {
  PointSet ps;
  add_cylinder(ps, {0, 0, 0}, {0, 0, 4}, 0.1, 0.02);
  // A tuft: a 10 cm ball of points 0.5 m beside the trunk at 3 m.
  for (int i = -2; i <= 2; ++i) {
    for (int j = -2; j <= 2; ++j) {
      for (int k = -2; k <= 2; ++k) ps.points.emplace_back(0.6 + 0.02 * i, 0.02 * j, 3 + 0.02 * k);
    }
  }
  EncodeOptions o;
  o.root_diameter_m = 0.2;
  const EncodeResult r = encode_point_set(ps, o);
  ASSERT_EQ(r.gaps.size(), 1u);
  EXPECT_NEAR(r.gaps[0].to.x(), 0.1, 0.02);  // the trunk's surface facing it
  EXPECT_NEAR(r.gaps[0].length_m, 0.46, 0.03);
}

// A crown floating above a bare stump (its lower part hidden): a 1 m stump, a gap of 0.5 m, a
// stem piece from 1.5 to 3 m, a gap of 0.5 m, and a leaning limb piece from 3.4 m whose axis
// points back at the stem piece's top, not at the stump. Joined each to the stump, the limb's
// piece would take a 2.4 m bridge across the open crown (its shortest edge, as no stump point
// lies in its cone); joined to the nearer piece first, both gaps are half a metre.
TEST(GapBridging, PiecesOfAFloatingCrownJoinEachOtherBeforeTheStump) {
  PointSet ps;
  add_cylinder(ps, {0, 0, 0}, {0, 0, 1}, 0.1, 0.02);     // stump
  add_cylinder(ps, {0, 0, 1.5}, {0, 0, 3}, 0.08, 0.02);  // stem piece
  const Eigen::Vector3d limb0(0.3, 0, 3.4), limb1(1.5, 0, 4.6);
  add_cylinder(ps, limb0, limb1, 0.05, 0.02);
  EncodeOptions o;
  o.root_diameter_m = 0.2;
  const EncodeResult r = encode_point_set(ps, o);
  ASSERT_EQ(r.gaps.size(), 2u);
  for (const BridgedGap& g : r.gaps) EXPECT_LT(g.length_m, 0.6);
  // One gap joins the stump's top to the stem piece's foot, the other the stem piece's top to
  // the limb's foot.
  const auto joins = [](const BridgedGap& g, double z_a, double z_b) {
    const double lo = std::min(g.from.z(), g.to.z()), hi = std::max(g.from.z(), g.to.z());
    return std::abs(lo - z_a) < 0.1 && std::abs(hi - z_b) < 0.1;
  };
  EXPECT_TRUE(joins(r.gaps[0], 1.0, 1.5) || joins(r.gaps[1], 1.0, 1.5));
  EXPECT_TRUE(joins(r.gaps[0], 3.0, 3.4) || joins(r.gaps[1], 3.0, 3.4));
}

}  // namespace
}  // namespace fspm::scans
