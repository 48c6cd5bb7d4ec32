#include "environment/cluster_grid_light.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include "environment/plastic_adaptation.hpp"
#include "environment/site_sky.hpp"
#include "environment/sky_distribution.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::environment {
namespace {

// The eight voxels whose centres surround x (voxel v has its centre at (v + 0.5) h) with their
// trilinear weights.
std::vector<std::pair<Eigen::Vector3i, double>> corners(double h, const Eigen::Vector3d& x) {
  const Eigen::Vector3d g = x / h - Eigen::Vector3d::Constant(0.5);
  const Eigen::Vector3d base = g.array().floor();
  std::vector<std::pair<Eigen::Vector3i, double>> out;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3i o(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    double w = 1.0;
    for (int a = 0; a < 3; ++a) w *= o[a] ? g[a] - base[a] : 1.0 - (g[a] - base[a]);
    out.emplace_back(base.cast<int>() + o, w);
  }
  return out;
}

// Palubicki's light of bud `self` written out directly from the buds, without summed-area
// tables, every bud's shade a spread over its eight surrounding voxel centres: at each of the
// query's corners, Q = max(C - s, 0) / C with s the sum of a w b^-q over the other buds' corner
// voxels q layers above (0 <= q <= q_max) and at most q voxels aside; the light is the corners'
// Q / C, each at most 1, weighted alike. At voxel centres this is Palubicki's grid.
double brute_bud_light(const ShadowGridParams& p, const std::vector<Eigen::Vector3d>& buds,
                       std::size_t self) {
  const double h = p.voxel_size_m;
  double light = 0.0;
  for (const auto& [v, wv] : corners(h, buds[self])) {
    if (wv <= 0.0) continue;
    double s = 0.0;
    for (std::size_t b = 0; b < buds.size(); ++b) {
      if (b == self) continue;
      for (const auto& [w, ww] : corners(h, buds[b])) {
        const int q = w.z() - v.z();
        if (q < 0 || q > p.depth_voxels) continue;
        if (std::abs(w.x() - v.x()) > q || std::abs(w.y() - v.y()) > q) continue;
        s += p.shade_a * ww * std::pow(p.shade_b, -q);
      }
    }
    light += wv * std::min(std::max(p.full_light - s, 0.0) / p.full_light, 1.0);
  }
  return light;
}

TEST(ClusterGridLight, ClusterLightIsTheMeanOfItsBudsPyramidLight) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const ShadowGridParams p = cluster_grid_params();
  std::vector<Eigen::Vector3d> buds, centers;
  std::vector<std::uint32_t> start{0};
  for (int c = 0; c < 40; ++c) {
    const Eigen::Vector3d center(1.5 * u(rng), 1.5 * u(rng), 2.0 + u(rng));
    centers.push_back(center);
    for (int k = 0; k < 12; ++k) {
      buds.push_back(center + 0.4 * Eigen::Vector3d(u(rng), u(rng), u(rng)));
    }
    start.push_back(static_cast<std::uint32_t>(buds.size()));
  }
  std::vector<std::uint8_t> alive(centers.size(), 1);
  alive[3] = 0;  // a dead cluster casts no shade and keeps its light
  std::vector<Eigen::Vector3d> live_buds;
  std::vector<std::size_t> live_index(buds.size(), 0);
  for (std::size_t c = 0; c < centers.size(); ++c) {
    if (!alive[c]) continue;
    for (std::uint32_t b = start[c]; b < start[c + 1]; ++b) {
      live_index[b] = live_buds.size();
      live_buds.push_back(buds[b]);
    }
  }
  std::vector<double> light(centers.size(), -1.0);
  std::vector<Eigen::Vector3d> direction(centers.size(), Eigen::Vector3d::Zero());
  const Scene open;
  ClusterGridLight grid(p, open);
  for (int pass = 0; pass < 2; ++pass) {  // the second pass reuses the grid's buffers
    grid.evaluate(buds, start, centers, alive, light, direction);
    for (std::size_t c = 0; c < centers.size(); ++c) {
      if (!alive[c]) {
        EXPECT_EQ(light[c], -1.0);
        continue;
      }
      double sum = 0.0;
      for (std::uint32_t b = start[c]; b < start[c + 1]; ++b) {
        sum += brute_bud_light(p, live_buds, live_index[b]);
      }
      EXPECT_NEAR(light[c], sum / 12.0, 1e-12) << c;
      EXPECT_NEAR(direction[c].norm(), 1.0, 1e-12);
      EXPECT_GT(direction[c].z(), 0.0);
    }
  }
}

// A bud passing under another, two layers down: its light follows the move in small steps. With
// the nearest voxel it jumps by a b^-q / C (0.05 here) as it enters or leaves the shadow pyramid
// (q = 2 voxels to each side); spread over the voxel centres no step of 1 cm changes it by more
// than a tenth of that. Far to either side it has full light, under the other bud a b^-q / C less.
TEST(ClusterGridLight, LightFollowsABudMovingUnderAnotherSmoothly) {
  const ShadowGridParams p = cluster_grid_params();
  const double h = p.voxel_size_m;
  const Eigen::Vector3d above(8.5 * h, 8.5 * h, 7.5 * h);
  const Scene open;
  ClusterGridLight grid(p, open);
  std::vector<double> lights;
  for (int step = 0; step <= 240; ++step) {
    const double x = above.x() - 4.0 * h + 0.01 * step;
    const std::vector<Eigen::Vector3d> buds{above, {x, 8.5 * h, 5.5 * h}};
    const std::vector<std::uint32_t> start{0, 1, 2};
    const std::vector<std::uint8_t> alive{1, 1};
    std::vector<double> light(2);
    std::vector<Eigen::Vector3d> direction(2);
    grid.evaluate(buds, start, buds, alive, light, direction);
    EXPECT_NEAR(light[0], 1.0, 1e-12);  // nothing above the upper bud
    if (!lights.empty()) {
      EXPECT_LT(std::abs(light[1] - lights.back()), 0.005) << x;
    }
    lights.push_back(light[1]);
  }
  EXPECT_NEAR(lights.front(), 1.0, 1e-12);
  EXPECT_NEAR(lights.back(), 1.0, 1e-12);
  EXPECT_NEAR(lights[120], 1.0 - p.shade_a * std::pow(p.shade_b, -2) / p.full_light, 1e-9);
}

TEST(ClusterGridLight, LightLeansAwayFromTheShadingSideByAtMostTheConesHalfAngle) {
  // One bud at voxel (0, 0, 1) shades the voxel below it, (0, 0, 0), by a / b; a point in voxel
  // (1, 0, 0) has that shade on its west and none on its east, so the light comes from the zenith
  // tilted east by atan((a / b) / C).
  ShadowGridParams p;
  ShadowGrid grid(p);
  const double h = p.voxel_size_m;
  grid.reset(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(2 * h));
  grid.add_bud(h * Eigen::Vector3d(0.5, 0.5, 1.5));
  grid.propagate();
  const Eigen::Vector3d d = grid.light_direction(h * Eigen::Vector3d(1.5, 0.5, 0.5));
  const double tilt = p.shade_a / p.shade_b / p.full_light;
  EXPECT_NEAR(d.x(), tilt / std::sqrt(1 + tilt * tilt), 1e-12);
  EXPECT_NEAR(d.y(), 0.0, 1e-12);
  // Beside an opaque wall the light leans away from it, by at most the cone's 45 degrees; beyond
  // the wall's reach (q_max voxels) it comes from the zenith.
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({-1, -1, 0}, {0, 1, 3}));
  ShadowGrid walled(p);
  walled.reset(Eigen::Vector3d(0, -0.5, 0), Eigen::Vector3d(3, 0.5, 1));
  walled.add_obstacles(scene);
  walled.propagate();
  const Eigen::Vector3d near = walled.light_direction({0.5 * h, 0.01, 0.5});
  EXPECT_GT(near.x(), 0.2);
  EXPECT_LE(near.x(), std::sqrt(0.5) + 1e-12);
  EXPECT_LT(std::abs(near.y()), 0.1 * near.x());
  const double beyond = (p.depth_voxels + 2.5) * h;
  EXPECT_EQ(walled.light_direction({beyond, 0.01, 0.5}), Eigen::Vector3d::UnitZ());
}

TEST(ClusterGridLight, SkyAndGridCombine) {
  double light = 0.6;
  Eigen::Vector3d direction = Eigen::Vector3d(0.5, 0.0, 1.0).normalized();
  combine_sky_and_grid(0.5, Eigen::Vector3d::UnitZ(), light, direction);
  EXPECT_DOUBLE_EQ(light, 0.3);
  EXPECT_NEAR((direction - Eigen::Vector3d(0.5, 0.0, 1.0).normalized()).norm(), 0.0, 1e-15);
  direction = Eigen::Vector3d::UnitZ();
  combine_sky_and_grid(1.0, Eigen::Vector3d(-1.0, 0.0, 0.0), light, direction);
  EXPECT_NEAR((direction - Eigen::Vector3d(-1.0, 0.0, 0.0)).norm(), 0.0, 1e-15);
}

TEST(ClusterGridLight, AdaptationUnderGridLightKeepsAnUnchangedTreeAndLeansAwayFromAWall) {
  const TreeGraph tree = read_tree_file(FSPM_SOURCE_DIR "/examples/trees/open_a12.treeb");
  AnalysisParams params;
  params.light_model = ClusterLightModel::kShadowGrid;
  const TreeAnalysis a = analyze_tree(tree, params);
  const AdaptationResult same = adapt_tree(tree, a, Scene{});
  EXPECT_EQ(same.pruned_nodes, 0u);
  EXPECT_EQ(same.light_evaluations, 0u);
  EXPECT_LT(same.mean_tip_displacement_m, 1e-9);
  Scene scene;
  scene.boxes.push_back(Box::wall({1.5, -20}, {1.5, 20}, 0.0, 20.0, 0.2));
  const AdaptationResult r = adapt_tree(tree, a, scene);
  EXPECT_LT(r.mean_tip_shift.x(), -0.1);
  EXPECT_GT(r.light_evaluations, 0u);
  // Two analyses with different light models cannot be adapted together.
  const TreeAnalysis sky = analyze_tree(tree);
  EXPECT_THROW(adapt_trees({&tree, &tree}, {&a, &sky}, scene), ValueError);
}

// Under the real sky of the equinox at 55 N the mean light direction leans about 38 degrees to the
// south (y north), and the cluster light's pyramids lean along it as growth's do: an opaque ball
// of radius 0.3 m two voxels (0.6 m) above a one-bud cluster and 0.45 m to its south shades it,
// the same ball as far to its north hardly; under the scene's own (zenith) sky both shade it
// alike, the vertical pyramid being symmetric. A cluster with nothing around it gets the zenith
// as its grid direction under either sky, so that combine_sky_and_grid gives it the sky's own
// mean direction, not that direction leaned a second time.
TEST(ClusterGridLight, RealSkyLeansTheShadeAwayFromTheSun) {
  SiteSky site;
  site.sky.site = {55.0, 0.0, 0.0, 0.0};
  site.sky.date = {2024, 3, 20};
  const auto real = std::make_shared<const SkyDistribution>(sky_distribution(site));
  const Eigen::Vector3d mean = real->mean_direction();
  ASSERT_LT(mean.y(), -0.3);
  const ShadowGridParams p = cluster_grid_params();
  const Eigen::Vector3d bud(0.15, 0.15, 2.55);
  // Light and grid direction of the one-bud cluster with the ball `ball_dy` to its north (y)
  // and 0.6 m above, and of a budless cluster 5 m away.
  const auto evaluate = [&](bool real_sky, double ball_dy, Eigen::Vector3d& open_direction) {
    Scene scene;
    scene.spheres.push_back({bud + Eigen::Vector3d(0.0, ball_dy, 0.6), 0.3, 0.0});
    if (real_sky) scene.sky.distribution = real;
    ClusterGridLight grid(p, scene);
    const std::vector<Eigen::Vector3d> buds{bud};
    const std::vector<Eigen::Vector3d> centers{bud, bud + Eigen::Vector3d(5.0, 0.0, 0.0)};
    const std::vector<std::uint32_t> start{0, 1, 1};
    const std::vector<std::uint8_t> alive{1, 1};
    std::vector<double> light(2);
    std::vector<Eigen::Vector3d> direction(2);
    grid.evaluate(buds, start, centers, alive, light, direction);
    EXPECT_NEAR(light[1], 1.0, 1e-12);
    open_direction = direction[1];
    return light[0];
  };
  Eigen::Vector3d open_real, open_zenith, unused;
  const double real_south = evaluate(true, -0.45, open_real);
  const double real_north = evaluate(true, 0.45, unused);
  const double zenith_south = evaluate(false, -0.45, open_zenith);
  const double zenith_north = evaluate(false, 0.45, unused);
  std::printf("55 N: ball south %.3f north %.3f; zenith: south %.3f north %.3f\n", real_south,
              real_north, zenith_south, zenith_north);
  EXPECT_LT(real_south, real_north - 0.05);
  EXPECT_LT(real_south, zenith_south);  // the ball is now up the light from the bud
  EXPECT_NEAR(zenith_south, zenith_north, 1e-12);
  EXPECT_LT(zenith_south, 1.0);
  EXPECT_NEAR((open_real - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_EQ(open_zenith, Eigen::Vector3d::UnitZ());
  double light = 1.0;
  combine_sky_and_grid(1.0, mean, light, open_real);
  EXPECT_NEAR((open_real - mean).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace fspm::environment
