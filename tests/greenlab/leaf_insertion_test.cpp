// Leaves on the axis surface with eased insertion angles (Jaeger 3.1.3), checked against
// geometry worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"
#include "fspm/instanced_tree.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A trunk of one metamer per cycle, no laterals, no phyllotaxy turn: its frame stays heading +z,
// left +y, so the leaves lean towards +y.
std::string trunk_plant(const std::string& leaf_keys, double radius_growth = 0.0) {
  return "[plant]\ncycles = 3\n[[age]]\nindex = 1\nduration = 100\nnext_age = 0\n"
         "units = [ { count = 1 } ]\nleaf_life_span = 0\nbranching_angle = 60\n"
         "phyllotaxy = 0\ninternode_length = 1\ninternode_radius = 0.1\nleaf_length = 0.5\n"
         "radius_growth = " +
         std::to_string(radius_growth) + "\n" + leaf_keys;
}

std::vector<NodeId> leaves_of(const TreeGraph& t) {
  std::vector<NodeId> out;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kLeaf) out.push_back(i);
  }
  return out;
}

// Distance from p to the line through a and b.
double distance_to_line(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = (b - a).normalized();
  const Eigen::Vector3d d = p - a;
  return (d - d.dot(u) * u).norm();
}

TEST(LeafInsertion, EasedAngleAtChosenPoints) {
  // s(x) = x^2 (3 - 2x): s(1/4) = 5/32, s(1/2) = 1/2, s(3/4) = 27/32.
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, 0), 60.0);
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, 1), 60.0 + 30.0 * 5.0 / 32.0);
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, 2), 75.0);
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, 3), 60.0 + 30.0 * 27.0 / 32.0);
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, 9), 90.0);   // opened
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 4, -1), 60.0);  // not born: closed
  EXPECT_DOUBLE_EQ(leaf_insertion_angle_deg(60, 30, 0, 0), 90.0);   // no opening time
  // Zero slope at both ends: x = 0.0025 gives s = 6.25e-6 * 2.995 = 1.871875e-5, 5.615625e-4
  // degrees (a linear ramp would give 0.075), and symmetrically near the end.
  EXPECT_NEAR(leaf_insertion_angle_deg(60, 30, 4, 0.01), 60.0 + 5.615625e-4, 1e-12);
  EXPECT_NEAR(leaf_insertion_angle_deg(60, 30, 4, 3.99), 90.0 - 5.615625e-4, 1e-12);
}

TEST(LeafInsertion, DefaultLeavesStayOnTheCentreLine) {
  const TreeGraph t = reconstruct(simulate_compressed(parse_plant_params(trunk_plant(""))), {});
  const auto leaves = leaves_of(t);
  ASSERT_EQ(leaves.size(), 3u);
  for (NodeId l : leaves) {
    EXPECT_TRUE(t.start(l).isApprox(t.end(t.parent(l))));
    EXPECT_NEAR(std::acos(t.direction(l).z()) / kDeg, 60.0, 1e-9);
  }
}

TEST(LeafInsertion, LeavesOnTheSurfaceOpenByHand) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(
      trunk_plant("leaf_on_surface = true\nleaf_angle_increase = 30\nleaf_opening = 2\n")));
  const TreeGraph t = reconstruct(g, {});
  const auto leaves = leaves_of(t);
  ASSERT_EQ(leaves.size(), 3u);
  // At age 3 the leaves born at 1, 2, 3 are 2, 1 and 0 cycles old: s = 1, 1/2, 0, angles 90, 75,
  // 60 degrees from the heading +z towards +y; they start at (0, 0.1, k), 0.1 from the axis.
  const double angle[3] = {90.0, 75.0, 60.0};
  for (int k = 0; k < 3; ++k) {
    const NodeId l = leaves[static_cast<std::size_t>(k)];
    const double a = angle[k] * kDeg;
    const Eigen::Vector3d start(0.0, 0.1, k + 1.0);
    const Eigen::Vector3d direction(0.0, std::sin(a), std::cos(a));
    EXPECT_TRUE((t.start(l) - start).norm() < 1e-12) << k << ": " << t.start(l).transpose();
    EXPECT_TRUE((t.direction(l) - direction).norm() < 1e-12) << k;
    EXPECT_TRUE((t.end(l) - (start + 0.5 * direction)).norm() < 1e-12) << k;
    EXPECT_NEAR(distance_to_line(t.start(l), t.start(t.parent(l)), t.end(t.parent(l))), 0.1, 1e-12);
  }
  // At age 2 the leaf of cycle 1 is one cycle old: half open, 75 degrees.
  ReconstructionOptions o;
  o.age = 2;
  const TreeGraph t2 = reconstruct(g, o);
  ASSERT_EQ(leaves_of(t2).size(), 2u);
  EXPECT_NEAR(std::acos(t2.direction(leaves_of(t2)[0]).z()) / kDeg, 75.0, 1e-9);
}

TEST(LeafInsertion, SurfaceFollowsTheRadiusAtTheReconstructedAge) {
  // Radius 0.1 at birth, + 0.05 per cycle: the metamer of cycle 1 ends at radius 0.2 at age 3;
  // at age 2 the quadratic interpolation gives 0.1 + 0.1 ((2 - 1) / (3 - 1))^2 = 0.125.
  const CompressedTreeGraph g =
      simulate_compressed(parse_plant_params(trunk_plant("leaf_on_surface = true\n", 0.05)));
  ReconstructionOptions o;
  o.age = 2;
  const TreeGraph t = reconstruct(g, o);
  const NodeId first = leaves_of(t)[0];
  EXPECT_NEAR(t.radius(t.parent(first)), 0.125, 1e-12);
  EXPECT_TRUE((t.start(first) - Eigen::Vector3d(0, 0.125, 1)).norm() < 1e-12);
}

TEST(LeafInsertion, EveryLeafOfABranchedPlantSitsOnItsInternodeSurface) {
  PlantParams p = testing::example("rauh.toml");
  for (auto& a : p.ages) {
    a.geometry.leaf_on_surface = true;
    a.geometry.leaf_angle_increase_deg = 20.0;
    a.geometry.leaf_opening_cycles = 1.5;
  }
  const CompressedTreeGraph g = simulate_compressed(p);
  const double now = g.birth_date + g.final_age;
  const TreeGraph t = reconstruct(g, {});
  std::size_t checked = 0;
  for (NodeId l : leaves_of(t)) {
    const NodeId m = t.parent(l);
    EXPECT_NEAR(distance_to_line(t.start(l), t.start(m), t.end(m)), t.radius(m), 1e-9);
    // At the top of the metamer: its projection on the axis is the internode's end.
    EXPECT_NEAR((t.start(l) - t.end(m)).dot(t.direction(m)), 0.0, 1e-9);
    const AgeParams& a = p.age(t.physiological_age(m));
    const double expected =
        leaf_insertion_angle_deg(a.geometry.branching_angle_deg, 20.0, 1.5, now - t.birth_time(l));
    EXPECT_NEAR(std::acos(std::clamp(t.direction(l).dot(t.direction(m)), -1.0, 1.0)) / kDeg,
                expected, 1e-7);
    ++checked;
  }
  EXPECT_GT(checked, 100u);
  // The instanced form and the line tree place them the same way.
  const TreeGraph expanded =
      expand_instanced_tree(reconstruct_instanced(g, {}), 10'000'000, ExpansionOrder::kAxisByAxis);
  const LineTree lines = reconstruct_lines(g, {});
  ASSERT_EQ(lines.size(), t.size());
  for (NodeId n = 0; n < t.size(); ++n) {
    EXPECT_LT((lines.starts()[n].cast<double>() - t.start(n)).norm(), 1e-4);
  }
  EXPECT_EQ(expanded.size(), reconstruct(g, {}).size());
}

TEST(LeafInsertion, SurfaceLeavesStillStopCollinearMerging) {
  const CompressedTreeGraph g =
      simulate_compressed(parse_plant_params(trunk_plant("leaf_on_surface = true\n")));
  ReconstructionOptions o;
  o.lod.merge_collinear = true;
  ReconstructionStats st;
  (void)reconstruct(g, o, &st);
  EXPECT_EQ(st.metamers, 3u);  // a leaf grows at each joint
  o.leaves = false;
  (void)reconstruct(g, o, &st);
  EXPECT_EQ(st.metamers, 1u);  // bare, the straight trunk is one internode
}

TEST(LeafInsertion, MetadataCarriesTheKeysOnlyWhenUsed) {
  const CompressedTreeGraph plain =
      simulate_compressed(parse_plant_params(trunk_plant("leaf_angle_increase = 0\n")));
  for (const auto& [key, value] : plain.metadata) {
    EXPECT_EQ(key.find("leaf_on_surface"), std::string::npos);
    EXPECT_EQ(key.find("leaf_angle"), std::string::npos);
    EXPECT_EQ(key.find("leaf_opening"), std::string::npos);
  }
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(
      trunk_plant("leaf_on_surface = true\nleaf_angle_increase = 30\nleaf_opening = 2\n")));
  const CompressedTreeGraph back = decode_ctree(encode_ctree(g));
  const TreeGraph a = reconstruct(g, {});
  const TreeGraph b = reconstruct(back, {});
  ASSERT_EQ(a.size(), b.size());
  for (NodeId n = 0; n < a.size(); ++n) EXPECT_EQ(a.start(n), b.start(n));
}

TEST(LeafInsertion, BadKeysAreRefusedWithTheirLine) {
  EXPECT_THROW(parse_plant_params(trunk_plant("leaf_on_surface = 1\n")), ParseError);
  EXPECT_THROW(parse_plant_params(trunk_plant("leaf_angle_increase = 200\n")), ParseError);
  EXPECT_THROW(parse_plant_params(trunk_plant("leaf_opening = -1\n")), ParseError);
}

}  // namespace
}  // namespace fspm::greenlab
