// Stray returns are left out, the sparse points of a crown are not.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "scans/isolated_points.hpp"

namespace fspm::scans {
namespace {

TEST(IsolatedPoints, StrayReturnsGoSparseCrownPointsStay) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  PointSet ps;
  // A stem 0.2 m thick and 3 m tall sampled every ~1 cm, and a crown of 400 points spread over a
  // ball of 2 m radius (about 0.4 m apart, forty times the stem's spacing).
  for (int k = 0; k < 20000; ++k) {
    const double a = 2.0 * std::numbers::pi * u(rng);
    ps.points.emplace_back(0.1 * std::cos(a), 0.1 * std::sin(a), 3.0 * u(rng));
  }
  for (int k = 0; k < 400;) {
    const Eigen::Vector3d d(2.0 * u(rng) - 1.0, 2.0 * u(rng) - 1.0, 2.0 * u(rng) - 1.0);
    if (d.norm() > 1.0) continue;
    ps.points.push_back(Eigen::Vector3d(0, 0, 5) + 2.0 * d);
    ++k;
  }
  const std::size_t tree = ps.points.size();
  // Three stray returns 6-15 m from the tree.
  ps.points.emplace_back(12.0, 0.0, 8.0);
  ps.points.emplace_back(0.0, -6.0, 2.0);
  ps.points.emplace_back(3.0, 9.0, 14.0);
  const IsolatedPoints r = remove_isolated_points(ps);
  EXPECT_EQ(r.removed, 3u);
  ASSERT_EQ(r.kept.points.size(), tree);
  for (std::size_t i = 0; i < tree; ++i) EXPECT_EQ(r.kept.points[i], ps.points[i]);
  EXPECT_GE(r.threshold_m, 1.0);
  EXPECT_LT(r.threshold_m, 6.0);
  // Too few points to judge: kept whole.
  PointSet few;
  few.points = {{0, 0, 0}, {100, 0, 0}};
  EXPECT_EQ(remove_isolated_points(few).kept.points.size(), 2u);
}

}  // namespace
}  // namespace fspm::scans
