#include "environment/canopy_summary.hpp"

#include "environment/canopy_light.hpp"
#include "environment/sky_distribution.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
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

namespace fspm::environment {
namespace {

// A horizontally homogeneous canopy: 7 layers of clusters 0.25 m apart over 10 m x 10 m (leaf
// area density 2.9 m2 m-3, leaf area index 5.1). Under a beam from the zenith the sunlit share of
// the leaves at a depth of leaf area index L is exp(-K L), K = G / cos(theta) = 0.5 (Campbell
// and Norman 1998, eq. 15.21), and the sunlit leaf area per ground area (1 - exp(-K L_t)) / K
// (eq. 15.23; de Pury and Farquhar 1997).
TEST(CanopyLightSummary, HomogeneousCanopyFollowsTheSunlitFractionExpMinusKL) {
  constexpr double s = 0.25, r = 0.25;
  constexpr int side = 41, layers = 7;
  std::vector<Sphere> clusters;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      for (int k = 0; k < layers; ++k) {
        clusters.push_back(
            {Eigen::Vector3d(i * s, j * s, 1.0 + k * s), r, std::pow(0.5, r), false});
      }
    }
  }
  // Leaf area per volume: each cluster's leaf area over the lattice's cell.
  const double lad = cluster_leaf_area_m2(clusters.front()) / (s * s * s);
  const double top = 1.0 + (layers - 1) * s + 0.5 * s;  // the layers' leaves end half a cell up
  const double lai = lad * layers * s;
  const CanopyLightSummary c = summarize_canopy_light(clusters, Sky{});
  double worst = 0.0;
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    // Columns at the edges hold less foliage (the spheres reach only r beyond them).
    const Eigen::Vector3d& p = clusters[k].center;
    if (std::min({p.x(), p.y(), (side - 1) * s - p.x(), (side - 1) * s - p.y()}) < 1.0) continue;
    const double depth_lai = lad * (top - clusters[k].center.z());
    if (p.x() == 5.0 && p.y() == 5.0) {
      std::printf("  layer at %.2f m: sunlit fraction %.3f, exp(-KL) %.3f\n", p.z(),
                  c.per_cluster[k].sunlit_fraction, std::exp(-0.5 * depth_lai));
    }
    // The top and bottom layers lie within a voxel (0.5 m) of the canopy's surfaces, where the
    // voxels smear the foliage (the top layer gets 0.73 for 0.83): checked in the sums only.
    if (p.z() < 1.1 || p.z() > top - s) continue;
    worst =
        std::max(worst, std::abs(c.per_cluster[k].sunlit_fraction - std::exp(-0.5 * depth_lai)));
  }
  const double ground = side * s * side * s;
  const double expected = ground * (1.0 - std::exp(-0.5 * lai)) / 0.5;
  std::printf(
      "homogeneous canopy, LAI %.2f: sunlit leaf area %.2f m2 (closed form %.2f), worst "
      "interior sunlit fraction off exp(-KL) by %.3f; LIE %.3f, STAR %.3f\n",
      lai, c.sunlit_leaf_area_m2, expected, worst, c.lie, c.star);
  EXPECT_NEAR(c.sunlit_leaf_area_m2, expected, 0.05 * expected);
  EXPECT_LT(worst, 0.02);
  EXPECT_NEAR(c.leaf_area_m2, lad * ground * layers * s, 1e-9 * c.leaf_area_m2);
  EXPECT_NEAR(c.sunlit_leaf_area_m2 + c.shaded_leaf_area_m2, c.leaf_area_m2, 1e-9);
  EXPECT_LT(c.star, 0.5 * (1.0 - std::exp(-0.5 * lai)) / (0.5 * lai) * 1.3);
}

// A lone, nearly transparent cluster under a real sky intercepts as leaves without shade: LIE 1,
// STAR 0.5, all leaves sunlit, and absorbs a_p G LA times the light on planes normal to each
// direction, sum_t S_b / sin(beta) + sum_d D_d / cos(theta_d) (written out here).
TEST(CanopyLightSummary, ALoneClusterAbsorbsTheOpenSkysLight) {
  RealSky day;
  day.site = {45.0, 7.0, 300.0, 1.0};
  day.date = {2024, 6, 21};
  const auto d = std::make_shared<const SkyDistribution>(sky_distribution(day));
  Sky sky;
  sky.directions = 64;
  apply_sky_distribution(sky, d);
  const std::vector<Sphere> one{{Eigen::Vector3d(0, 0, 2), 0.05, 0.9999, false}};
  const CanopyLightSummary c = summarize_canopy_light(one, sky);
  double normal = 0.0;
  for (std::size_t k = 0; k < d->suns.size(); ++k) {
    if (d->direct_mol_m2[k] > 0.0) normal += d->direct_mol_m2[k] / d->suns[k].z();
  }
  const HemisphereDirections dirs(64);
  for (std::size_t k = 0; k < d->suns.size(); ++k) {
    double sum = 0.0;
    std::vector<double> w(64);
    for (int i = 0; i < 64; ++i) {
      w[i] = (1.0 + 2.0 * dirs.direction(i).z()) / 3.0 * dirs.direction(i).z();  // CIE overcast
      sum += w[i];
    }
    for (int i = 0; i < 64; ++i)
      normal += d->diffuse_mol_m2[k] * w[i] / sum / dirs.direction(i).z();
  }
  const double expected = 0.8 * 0.5 * cluster_leaf_area_m2(one[0]) * normal;
  ASSERT_TRUE(c.real_sky);
  EXPECT_NEAR(c.absorbed_par_mol_day, expected, 1e-3 * expected);
  EXPECT_NEAR(c.lie, 1.0, 1e-3);
  EXPECT_NEAR(c.star, 0.5, 1e-3);
  EXPECT_NEAR(c.sunlit_leaf_area_m2, c.leaf_area_m2, 1e-3 * c.leaf_area_m2);
}

}  // namespace
}  // namespace fspm::environment
