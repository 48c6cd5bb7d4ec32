#include "environment/cluster_grid_light.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::environment {
namespace {

// Palubicki's light of a bud written out directly from the buds, without summed-area tables:
// Q = max(C - s + a, 0) / C with s the sum of a * b^-q over every bud whose voxel lies q layers
// above (0 <= q <= q_max) and at most q voxels aside.
double brute_bud_light(const ShadowGridParams& p, const std::vector<Eigen::Vector3d>& buds,
                       const Eigen::Vector3d& at) {
  const auto voxel = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3i((x / p.voxel_size_m).array().floor().cast<int>());
  };
  const Eigen::Vector3i v = voxel(at);
  double s = 0.0;
  for (const Eigen::Vector3d& b : buds) {
    const Eigen::Vector3i w = voxel(b);
    const int q = w.z() - v.z();
    if (q < 0 || q > p.depth_voxels) continue;
    if (std::abs(w.x() - v.x()) > q || std::abs(w.y() - v.y()) > q) continue;
    s += p.shade_a * std::pow(p.shade_b, -q);
  }
  return std::min(std::max(p.full_light - s + p.shade_a, 0.0) / p.full_light, 1.0);
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
  for (std::size_t c = 0; c < centers.size(); ++c) {
    if (alive[c])
      live_buds.insert(live_buds.end(), buds.begin() + start[c], buds.begin() + start[c + 1]);
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
        sum += brute_bud_light(p, live_buds, buds[b]);
      }
      EXPECT_NEAR(light[c], sum / 12.0, 1e-12) << c;
      EXPECT_NEAR(direction[c].norm(), 1.0, 1e-12);
      EXPECT_GT(direction[c].z(), 0.0);
    }
  }
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

}  // namespace
}  // namespace fspm::environment
