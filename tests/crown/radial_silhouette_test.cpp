// Argudo's radial silhouette (4.2) against shapes whose radii are known.
#include "crown/radial_silhouette.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

TEST(RadialSilhouette, DiscHasOneRadiusInEveryDirection) {
  Mask m(128, 128);
  for (int y = 0; y < 128; ++y) {
    for (int x = 0; x < 128; ++x) m.set(x, y, std::hypot(x - 63.5, y - 63.5) <= 40.0);
  }
  const RadialSilhouette r(m);
  std::mt19937_64 rng(4);
  std::normal_distribution<double> g;
  for (int k = 0; k < 200; ++k) {
    EXPECT_NEAR(r.radius_px(Eigen::Vector3d(g(rng), g(rng), g(rng))), 40.0, 1.0);
  }
}

TEST(RadialSilhouette, SquareReachesItsCornersAndRevolvesItsProfile) {
  Mask m(100, 100);
  for (int y = 30; y < 70; ++y) {
    for (int x = 20; x < 80; ++x) m.set(x, y, true);  // 60 wide, 40 high, centre (49.5, 49.5)
  }
  const RadialSilhouette r(m);
  EXPECT_NEAR(r.radius_px(0.0), 29.5, 0.5);                                       // right edge
  EXPECT_NEAR(r.radius_px(M_PI / 2), 19.5, 0.5);                                  // top edge
  EXPECT_NEAR(r.radius_px(std::atan2(19.5, 29.5)), std::hypot(29.5, 19.5), 1.0);  // corner
  // Straight away from the camera the horizontal profile is the mean of right and left: 29.5.
  EXPECT_NEAR(r.radius_px(Eigen::Vector3d(0, 1, 0)), 29.5, 0.5);
  EXPECT_NEAR(r.radius_px(Eigen::Vector3d(0, 0, 1)), 19.5, 0.5);
}

TEST(RadialSilhouette, KeepsTheLastIntersection) {
  Mask m(100, 100);  // a disc and, beyond a gap to the right, a bar: the ray ends on the bar
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      m.set(
          x, y,
          std::hypot(x - 40.0, y - 50.0) <= 20.0 || (x >= 80 && x <= 84 && std::abs(y - 50) <= 2));
    }
  }
  const RadialSilhouette r(m);
  EXPECT_GT(r.radius_px(0.0), 40.0);
  EXPECT_THROW(RadialSilhouette(Mask(8, 8)), ValueError);
}

}  // namespace
}  // namespace fspm::crown
