#include "environment/canopy_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/growth_model.hpp"

namespace fspm::environment {
namespace {

// One cluster: the silhouette is the disc's integral of 1 - exp(-2 mu sqrt(r^2 - rho^2)),
// pi r^2 - 2 pi (1 - exp(-2 mu r)(1 + 2 mu r)) / (4 mu^2), from any direction.
TEST(CanopySummary, OneClusterInClosedForm) {
  const double r = 0.5, gamma = 0.2, mu = -std::log(gamma) / (2 * r);
  const std::vector<Sphere> one{{Eigen::Vector3d(1, 2, 3), r, gamma, false}};
  const double pi = std::numbers::pi;
  const double expected =
      pi * r * r - 2 * pi * (1 - std::exp(-2 * mu * r) * (1 + 2 * mu * r)) / (4 * mu * mu);
  for (const Eigen::Vector3d& sun : {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, -1, 2)}) {
    const CanopySummary s = summarize_canopy(one, sun, 0.004);
    EXPECT_NEAR(s.silhouette_area_m2, expected, 0.005 * expected);
    EXPECT_NEAR(s.leaf_area_m2, cluster_leaf_area_m2(one[0]), 1e-12);
    EXPECT_NEAR(s.sunlit_leaf_area_m2 + s.shaded_leaf_area_m2, s.leaf_area_m2, 1e-12);
    EXPECT_NEAR(s.sunlit_leaf_area_m2, s.silhouette_area_m2 / 0.5, 1e-12);
    EXPECT_LT(s.star, 0.5);
  }
}

// Leaves that hardly shade each other: STAR tends to G = 0.5 (spherical leaf angles), every leaf
// in the sun.
TEST(CanopySummary, SparseFoliageHasAStarOfOneHalf) {
  const std::vector<Sphere> sparse{{Eigen::Vector3d(0, 0, 2), 0.4, 0.999, false},
                                   {Eigen::Vector3d(3, 0, 2), 0.3, 0.999, false}};
  const CanopySummary s = summarize_canopy(sparse, Eigen::Vector3d::UnitZ(), 0.004);
  EXPECT_NEAR(s.star, 0.5, 0.005);
  EXPECT_NEAR(s.sunlit_leaf_area_m2 / s.leaf_area_m2, 1.0, 0.01);
}

// A grown crown shades itself: STAR well below 0.5, most leaves in the shade of the zenith sun.
TEST(CanopySummary, GrownCrownShadesItself) {
  GrowthParams p = growth_preset("A");
  p.years = 15;
  const GrowthResult g = grow_tree(p);
  const CanopySummary s = summarize_canopy(g.cluster_spheres);
  std::printf("15-year type A: leaf area %.2f m2, silhouette %.2f m2, sunlit %.2f m2, STAR %.3f\n",
              s.leaf_area_m2, s.silhouette_area_m2, s.sunlit_leaf_area_m2, s.star);
  EXPECT_EQ(s.clusters, g.cluster_spheres.size());
  EXPECT_GT(s.star, 0.05);
  EXPECT_LT(s.star, 0.4);
  EXPECT_LT(s.sunlit_leaf_area_m2, s.shaded_leaf_area_m2 + s.sunlit_leaf_area_m2);
}

}  // namespace
}  // namespace fspm::environment
