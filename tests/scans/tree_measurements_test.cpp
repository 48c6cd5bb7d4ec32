// Measurements of scanned trees (TreeQSM-like) against trees of known geometry, recentring of
// projected coordinates, and the warnings for clouds that are not one tree.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "scans/circle_fit.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/scanned_tree.hpp"
#include "scans/synthetic_tree.hpp"
#include "scans/tree_measurements.hpp"

namespace fspm::scans {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CircleFit, StaysExactAtProjectedCoordinates) {
  // A third of a circle of radius 0.15 m at x ~ 5e5, y ~ 5.8e6 m: squares of the raw
  // coordinates (3.4e13) would leave nothing of the radius.
  const Eigen::Vector2d centre(500000.3, 5800000.7);
  std::vector<Eigen::Vector2d> arc;
  for (int k = 0; k < 50; ++k) {
    const double a = 2.0 * kPi / 3.0 * k / 49.0;
    arc.push_back(centre + 0.15 * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  const std::optional<Circle> c = fit_circle_kasa(arc);
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->radius_m, 0.15, 1e-6);
  EXPECT_LT((c->centre - centre).norm(), 1e-6);
  EXPECT_FALSE(fit_circle_kasa({{0, 0}, {1, 1}, {2, 2}, {3, 3}}));  // collinear
}

struct Truth {
  double dbh_m = 0.0, height_m = 0.0, volume_m3 = 0.0, length_m = 0.0;
  double crown_base_m = 1e9;  // the lowest fork of a main branch
};

// Closed forms on the synthetic tree: its internodes are cylinders.
Truth truth_of(const TreeGraph& t) {
  Truth out;
  for (NodeId u = 0; u < t.size(); ++u) {
    out.volume_m3 += kPi * t.radius(u) * t.radius(u) * t.length(u);
    out.length_m += t.length(u);
    if (t.order(u) == 1 && t.order(t.parent(u)) == 0) {
      out.crown_base_m = std::min(out.crown_base_m, t.end(t.parent(u)).z());
    }
    out.height_m = std::max(out.height_m, t.end(u).z());
    if (t.order(u) == 0 && t.start(u).z() <= 1.3 && t.end(u).z() > 1.3) {
      out.dbh_m = 2.0 * t.radius(u);
    }
  }
  return out;
}

PointSet scan_of(const TreeGraph& tree, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return simulate_scan(tree, ScanOptions{}, rng);
}

TEST(TreeMeasurements, SyntheticTreesWithinTheirKnownGeometry) {
  SyntheticTreeOptions thin;
  thin.root_diameter_m = 0.2;
  thin.trunk_length_m = 7.0;
  thin.branches = 5;
  for (const SyntheticTreeOptions& options : {SyntheticTreeOptions{}, thin}) {
    const TreeGraph tree = synthetic_tree(options);
    const Truth truth = truth_of(tree);
    for (std::uint64_t seed : {1, 2, 3}) {
      const PointSet scan = scan_of(tree, seed);
      const EncodeResult r = encode_point_set(scan);
      const TreeMeasurements m = measure_tree(scan, r.full_skeleton);
      SCOPED_TRACE("trunk " + std::to_string(options.trunk_length_m) + " m, seed " +
                   std::to_string(seed));
      std::printf(
          "%.0f m, %d | %zu | %.4f m (%.4f) | %.3f m (%.3f) | %.3f m3 (%.3f) | %.2f m (%.2f) | "
          "%.2f | %zu\n",
          options.trunk_length_m, static_cast<int>(seed), scan.points.size(), m.dbh_m.value_or(0.0),
          truth.dbh_m, m.height_m, truth.height_m, m.woody_volume_m3, truth.volume_m3,
          m.crown_base_m.value_or(0.0), truth.crown_base_m, m.points_explained_fraction,
          m.cylinders.size());
      EXPECT_TRUE(m.tree_found);
      EXPECT_TRUE(m.warnings.empty()) << m.warnings.at(0);
      ASSERT_TRUE(m.dbh_m);
      EXPECT_NEAR(*m.dbh_m, truth.dbh_m, 0.03 * truth.dbh_m);
      EXPECT_NEAR(m.height_m, truth.height_m, 0.02 * truth.height_m);
      EXPECT_NEAR(m.woody_volume_m3, truth.volume_m3, 0.15 * truth.volume_m3);
      ASSERT_TRUE(m.crown_base_m);
      EXPECT_NEAR(*m.crown_base_m, truth.crown_base_m, 0.05);
      EXPECT_GT(m.points_explained_fraction, 0.8);
      ASSERT_GE(m.branches_per_order.size(), 2u);
      EXPECT_EQ(m.branches_per_order[0], 1u);
      // The order-0 axis is the trunk, continued into a main branch where the skeleton's largest
      // subtree goes on there (the trunk's top above the last branch is short).
      EXPECT_GT(m.branch_length_per_order_m[0], 0.7 * options.trunk_length_m);
      EXPECT_LT(m.branch_length_per_order_m[0], options.trunk_length_m + options.branch_length_m);
      double total = 0.0;
      for (double l : m.branch_length_per_order_m) total += l;
      // Through bin centroids of surface points the skeleton runs longer than the axes.
      EXPECT_NEAR(total, truth.length_m, 0.35 * truth.length_m);
    }
  }
}

// Leaves: a leafy crown scanned (leaf clumps of 0.3 m radius about the end of every branch and
// twig internode, 300 points each: 16 800, a fifth of the points). The woody volume stays within
// 25 % of the wood's: the clumps' points spread about a branch are no surface a circle fits,
// and such a branch's radius comes from the pipe model, not from the spread of its leaves (with
// the median distance of the points from the axis the volume came out 62-68 % too high).
TEST(TreeMeasurements, LeavesAreNotWood) {
  const TreeGraph tree = synthetic_tree();
  const Truth truth = truth_of(tree);
  for (std::uint64_t seed : {1, 2}) {
    PointSet scan = scan_of(tree, seed);
    std::mt19937_64 rng(seed + 100);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::size_t wood = scan.points.size();
    for (NodeId n = 0; n < tree.size(); ++n) {
      if (tree.order(n) == 0) continue;
      for (int k = 0; k < 300;) {
        const Eigen::Vector3d d(u(rng), u(rng), u(rng));
        if (d.norm() > 1.0) continue;
        scan.points.push_back(tree.end(n) + 0.3 * d);
        ++k;
      }
    }
    SCOPED_TRACE(seed);
    ASSERT_GT(scan.points.size() - wood, 2000u);
    const TreeMeasurements m = measure_tree(scan, encode_point_set(scan).full_skeleton);
    std::printf("leafy, seed %d: %zu wood + %zu leaf points, volume %.3f m3 (%.3f)\n",
                static_cast<int>(seed), wood, scan.points.size() - wood, m.woody_volume_m3,
                truth.volume_m3);
    EXPECT_NEAR(m.woody_volume_m3, truth.volume_m3, 0.25 * truth.volume_m3);
    ASSERT_TRUE(m.dbh_m);
    EXPECT_NEAR(*m.dbh_m, truth.dbh_m, 0.03 * truth.dbh_m);
  }
}

// The same cloud moved to projected coordinates gives the same skeleton to 1 mm and the same
// measurements; the cylinders come back in the moved coordinates.
TEST(TreeMeasurements, ProjectedCoordinatesGiveTheSameTreeToAMillimetre) {
  const PointSet scan = scan_of(synthetic_tree(), 1);
  const Eigen::Vector3d shift(500000.0, 5800000.0, 300.0);
  PointSet moved = scan;
  for (Eigen::Vector3d& p : moved.points) p += shift;
  const EncodeResult a = encode_point_set(scan), b = encode_point_set(moved);
  ASSERT_EQ(a.full_skeleton.size(), b.full_skeleton.size());
  for (NodeId u = 0; u < a.full_skeleton.size(); ++u) {
    EXPECT_LT((b.full_skeleton.end(u) - shift - a.full_skeleton.end(u)).norm(), 1e-3) << u;
  }
  EXPECT_NEAR(a.model.root_diameter_m, b.model.root_diameter_m, 1e-3);
  const TreeMeasurements ma = measure_tree(scan, a.full_skeleton);
  const TreeMeasurements mb = measure_tree(moved, b.full_skeleton);
  ASSERT_TRUE(ma.dbh_m && mb.dbh_m);
  EXPECT_NEAR(*ma.dbh_m, *mb.dbh_m, 1e-3);
  EXPECT_NEAR(ma.woody_volume_m3, mb.woody_volume_m3, 1e-3 * ma.woody_volume_m3);
  ASSERT_EQ(ma.cylinders.size(), mb.cylinders.size());
  EXPECT_LT((mb.cylinders[3].start - shift - ma.cylinders[3].start).norm(), 1e-3);
}

// Points on the walls of a 8 m x 6 m house, 3 m high, every 5 cm.
PointSet house() {
  PointSet ps;
  for (double z = 0.0; z <= 3.0; z += 0.05) {
    for (double s = 0.0; s < 8.0; s += 0.05) {
      ps.points.emplace_back(s, 0.0, z), ps.points.emplace_back(s, 6.0, z);
    }
    for (double s = 0.0; s < 6.0; s += 0.05) {
      ps.points.emplace_back(0.0, s, z), ps.points.emplace_back(8.0, s, z);
    }
  }
  return ps;
}

bool has_warning(const TreeMeasurements& m, const std::string& text) {
  for (const std::string& w : m.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

EncodeOptions with_root_diameter() {
  EncodeOptions o;
  o.root_diameter_m = 0.3;  // no trunk to fit one from
  return o;
}

TEST(TreeMeasurements, AHouseIsNoTree) {
  const PointSet ps = house();
  const TreeMeasurements m =
      measure_tree(ps, encode_point_set(ps, with_root_diameter()).full_skeleton);
  EXPECT_FALSE(m.tree_found);
  EXPECT_FALSE(m.dbh_m);
  EXPECT_TRUE(has_warning(m, "no vertical trunk")) << m.warnings.size();
}

// The house with a gable roof (ridge 5 m high), the ground about it every 0.1 m and a post of
// 0.14 m beside it, 0.3 m high (a public scan of a house has one): the post stands as a stem at
// the foot, but the walls are 24 m2 of flat vertical surface.
TEST(TreeMeasurements, AHouseWithARoofAndAPostIsABuilding) {
  PointSet ps = house();
  for (double s = 0.0; s < 8.0; s += 0.05) {
    for (double t = 0.0; t <= 3.0; t += 0.05) {
      ps.points.emplace_back(s, t, 3.0 + 2.0 * t / 3.0);
      ps.points.emplace_back(s, 6.0 - t, 3.0 + 2.0 * t / 3.0);
    }
  }
  for (double x = -3.0; x < 11.0; x += 0.1) {
    for (double y = -3.0; y < 9.0; y += 0.1) ps.points.emplace_back(x, y, 0.0);
  }
  for (double z = 0.0; z < 0.3; z += 0.01) {
    for (int k = 0; k < 24; ++k) {
      const double a = 2.0 * std::numbers::pi * k / 24.0;
      ps.points.emplace_back(-1.0 + 0.07 * std::cos(a), 3.0 + 0.07 * std::sin(a), z);
    }
  }
  const ScannedTree t = encode_and_measure(ps, with_root_diameter());
  EXPECT_FALSE(t.measurements.tree_found);
  ASSERT_FALSE(t.measurements.warnings.empty());
  EXPECT_NE(t.measurements.warnings.front().find("a building, not a tree"), std::string::npos)
      << t.measurements.warnings.front();
}

// A scanned tree 3 m from the 8 m wall of a building whose ground floor the scan does not see
// (the wall from 2 m to 5 m): still a tree, with its diameter, and a warning that the building is
// in the scan. (A wall down to the ground takes the trunk's place in the skeleton: cut it out.)
TEST(TreeMeasurements, ATreeBesideAWallKeepsItsDiameter) {
  const TreeGraph tree = synthetic_tree(SyntheticTreeOptions{});
  PointSet ps = scan_of(tree, 1);
  const double x0 = tree.start(0).x() + 3.0;
  for (double z = 2.0; z <= 5.0; z += 0.05) {
    for (double y = -4.0; y < 4.0; y += 0.05) ps.points.emplace_back(x0, tree.start(0).y() + y, z);
  }
  const TreeMeasurements m = measure_tree(ps, encode_point_set(ps).full_skeleton);
  EXPECT_TRUE(m.tree_found);
  ASSERT_TRUE(m.dbh_m);
  EXPECT_NEAR(*m.dbh_m, truth_of(tree).dbh_m, 0.03 * truth_of(tree).dbh_m);
  EXPECT_TRUE(has_warning(m, "cut the building out")) << m.warnings.size();
}

TEST(TreeMeasurements, TwoTreesAreSeveralStems) {
  const TreeGraph tree = synthetic_tree();
  PointSet ps = scan_of(tree, 1);
  const PointSet other = scan_of(tree, 2);
  for (const Eigen::Vector3d& p : other.points) ps.points.push_back(p + Eigen::Vector3d(4, 0, 0));
  const TreeMeasurements m =
      measure_tree(ps, encode_point_set(ps, with_root_diameter()).full_skeleton);
  EXPECT_EQ(m.stems, 2u);
  EXPECT_TRUE(has_warning(m, "2 separate stems"));
  EXPECT_TRUE(m.tree_found);
}

TEST(TreeMeasurements, TooFewPointsAtBreastHeightGiveNoDiameter) {
  // An airborne-like cloud: 7 points below 1.5 m, a crown of 2 000 above 3 m.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PointSet ps;
  for (int k = 0; k < 7; ++k) ps.points.emplace_back(0.1 * u(rng), 0.1 * u(rng), 0.2 * (k + 1));
  for (int k = 0; k < 2000; ++k) ps.points.emplace_back(2 * u(rng), 2 * u(rng), 5 + 2 * u(rng));
  const TreeMeasurements m =
      measure_tree(ps, encode_point_set(ps, with_root_diameter()).full_skeleton);
  EXPECT_FALSE(m.dbh_m);
  EXPECT_LE(m.breast_height_points, 2u);
  EXPECT_TRUE(has_warning(m, "trunk points 1.2-1.4 m above the lowest point (at least 20"));
  EXPECT_NEAR(m.height_m, 7.0 - 0.2, 0.1);  // from the lowest point at 0.2 m
}

}  // namespace
}  // namespace fspm::scans
