#include "scans/vertical_plane.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace fspm::scans {
namespace {

// One wall 8 m long and 3 m high, turned 30 degrees, its points every 5 cm with 1 cm of noise
// across it, standing on ground 0.6 m below its foot: the flat area is the wall's, 24 m2, to the
// cells cut by its edges (0.5 m cells: at most 8.5 x 3.5 m).
TEST(VerticalPlane, AWallHasItsArea) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.01);
  const double c = std::cos(std::numbers::pi / 6.0), s = std::sin(std::numbers::pi / 6.0);
  PointSet ps;
  ps.points.emplace_back(0.0, 0.0, -0.6);
  for (double z = 0.0; z <= 3.0; z += 0.05) {
    for (double u = 0.0; u < 8.0; u += 0.05) {
      const double n = noise(rng);
      ps.points.emplace_back(500000.0 + c * u - s * n, 5800000.0 + s * u + c * n, z);
    }
  }
  ps.points[0] += ps.points[1];
  const auto wall = largest_vertical_plane(ps);
  ASSERT_TRUE(wall);
  EXPECT_GT(wall->area_m2, 0.8 * 24.0);
  EXPECT_LE(wall->area_m2, 8.5 * 3.5);
  EXPECT_GT(wall->share, 0.9);
}

// A cloud filling a crown-like ball of 3 m radius: no flat cell of any slab.
TEST(VerticalPlane, ACrownHasNone) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  PointSet ps;
  ps.points.emplace_back(0.0, 0.0, 0.0);
  while (ps.points.size() < 40000) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    if (p.norm() < 3.0) ps.points.push_back(p + Eigen::Vector3d(0.0, 0.0, 5.0));
  }
  const auto wall = largest_vertical_plane(ps);
  EXPECT_TRUE(!wall || wall->area_m2 < 1.0) << wall->area_m2;
}

}  // namespace
}  // namespace fspm::scans
