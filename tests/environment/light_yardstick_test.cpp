// An independent yardstick for the light of leaf clusters: Monte Carlo ray tracing over explicit
// leaf and branch triangles (leaf_ray_tracer.hpp). The light models are compared with it per
// cluster.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/canopy_sweep.hpp"
#include "environment/cluster_grid_light.hpp"
#include "environment/growth_model.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/light_model.hpp"
#include "tests/environment/leaf_ray_tracer.hpp"

namespace fspm::environment {
namespace {

using yardstick::add_wood;
using yardstick::Bvh;
using yardstick::leaf_triangles;
using yardstick::traced_light;
using yardstick::Triangle;

struct Agreement {
  double mae = 0.0, bias = 0.0, r = 0.0;
};

Agreement compare(std::span<const double> model, std::span<const double> truth) {
  const double n = static_cast<double>(truth.size());
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) mx += model[i] / n, my += truth[i] / n;
  Agreement a;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    a.mae += std::abs(model[i] - truth[i]) / n;
    a.bias += (model[i] - truth[i]) / n;
    sxy += (model[i] - mx) * (truth[i] - my);
    sxx += (model[i] - mx) * (model[i] - mx);
    syy += (truth[i] - my) * (truth[i] - my);
  }
  a.r = sxy / std::sqrt(sxx * syy);
  return a;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Every cluster-light estimate against the ray-traced leaves of an open-grown tree per preset.
TEST(LightYardstick, ClusterLightAgainstRayTracedLeaves) {
  for (const char* type : {"A", "B", "C"}) {
    GrowthParams params = growth_preset(type);
    params.years = 15;
    const GrowthResult g = grow_tree(params);
    std::mt19937_64 rng(7);
    std::vector<std::uint32_t> leaf_start;
    std::vector<Triangle> tris = leaf_triangles(g.cluster_spheres, rng, leaf_start);
    add_wood(g.tree, tris);
    auto t0 = std::chrono::steady_clock::now();
    const Bvh bvh(tris);
    const std::vector<double> truth = traced_light(bvh, tris, leaf_start, 16, 64, rng);
    const double traced_s = seconds_since(t0);
    const std::size_t n = g.cluster_spheres.size();

    // Pirk eq. 4.3 at the centre (the former leaf light; the adaptation's `sky` cluster light).
    t0 = std::chrono::steady_clock::now();
    Scene s;
    s.spheres = g.cluster_spheres;
    const LightModel eq43(s);
    std::vector<double> centre(n);
    for (std::uint32_t c = 0; c < n; ++c) {
      centre[c] = eq43.evaluate(g.cluster_spheres[c].center, c).light;
    }
    const double eq43_s = seconds_since(t0);
    // Turbid medium at the centre with the cluster's own leaves (record_leaf_light), and at the
    // top of each cluster without them.
    t0 = std::chrono::steady_clock::now();
    const CanopyLight canopy(Scene{}, g.cluster_spheres);
    std::vector<double> top(n), mid(n);
    for (std::uint32_t c = 0; c < n; ++c) {
      mid[c] = canopy.evaluate(g.cluster_spheres[c].center).light;
    }
    const double canopy_s = seconds_since(t0);
    for (std::uint32_t c = 0; c < n; ++c) {
      top[c] = canopy.evaluate(cluster_top(g.cluster_spheres[c]), c).light;
    }
    // The same through voxels of 0.1 m (LeafAreaGrid).
    t0 = std::chrono::steady_clock::now();
    const CanopyLight voxels(Scene{}, g.cluster_spheres, 0.1);
    std::vector<double> voxel_light(n);
    for (std::uint32_t c = 0; c < n; ++c) {
      voxel_light[c] = voxels.evaluate(g.cluster_spheres[c].center).light;
    }
    const double voxel_s = seconds_since(t0);
    // Shadow grid per cluster (the adaptation's `shadow_grid`): each cluster's bud at the end of
    // its shoot.
    t0 = std::chrono::steady_clock::now();
    std::vector<Eigen::Vector3d> buds, centres;
    std::vector<std::uint32_t> bud_start{0};
    for (NodeId i = 0; i < g.tree.size(); ++i) {
      if (g.tree.kind(i) != OrganKind::kLeaf) continue;
      buds.push_back(g.tree.end(g.tree.parent(i)));
      centres.push_back(g.tree.start(i));
      bud_start.push_back(static_cast<std::uint32_t>(buds.size()));
    }
    const Scene open;
    ClusterGridLight grid(cluster_grid_params(), open);
    std::vector<double> grid_light(n);
    std::vector<Eigen::Vector3d> grid_dir(n);
    const std::vector<std::uint8_t> alive(n, 1);
    grid.evaluate(buds, bud_start, centres, alive, grid_light, grid_dir);
    const double grid_s = seconds_since(t0);
    // The leaf light models of the registry as the adaptation's `canopy` light uses them (the
    // adaptation's 64 directions), and the sweep at other voxel sizes.
    Sky sky64;
    sky64.directions = 64;
    std::vector<LightSample> lit(n);
    t0 = std::chrono::steady_clock::now();
    make_leaf_light_model("sweep", sky64)->evaluate(g.cluster_spheres, {}, lit);
    const double sweep_s = seconds_since(t0);
    std::vector<double> sweep_light(n), sweep_fine(n), sweep_coarse(n);
    for (std::size_t c = 0; c < n; ++c) sweep_light[c] = lit[c].light;
    const auto sweep_at = [&](double voxel_m, std::vector<double>& out) {
      CanopySweep sweep(64, Eigen::Vector3d::UnitZ(), voxel_m);
      std::vector<Eigen::Vector3d> at(n);
      for (std::size_t c = 0; c < n; ++c) at[c] = g.cluster_spheres[c].center;
      sweep.evaluate(g.cluster_spheres, at, {}, lit);
      for (std::size_t c = 0; c < n; ++c) out[c] = lit[c].light;
    };
    t0 = std::chrono::steady_clock::now();
    sweep_at(0.25, sweep_fine);
    const double sweep_fine_s = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    sweep_at(0.4, sweep_coarse);
    const double sweep_coarse_s = seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    make_leaf_light_model("turbid", sky64)->evaluate(g.cluster_spheres, {}, lit);
    const double turbid64_s = seconds_since(t0);
    std::vector<double> turbid64(n);
    for (std::size_t c = 0; c < n; ++c) turbid64[c] = lit[c].light;

    double mean_truth = 0.0;
    for (const double v : truth) mean_truth += v / static_cast<double>(n);
    std::printf(
        "preset %s, 15 years: %zu clusters, %zu triangles, mean traced leaf light %.3f "
        "(%.2f s)\n",
        type, n, tris.size(), mean_truth, traced_s);
    const struct {
      const char* name;
      const std::vector<double>& values;
      double seconds;
    } rows[] = {{"eq. 4.3 at the centre", centre, eq43_s},
                {"turbid medium, centre (leaf light)", mid, canopy_s},
                {"turbid medium, top", top, canopy_s},
                {"turbid medium, centre, 0.1 m voxels", voxel_light, voxel_s},
                {"shadow grid per cluster", grid_light, grid_s},
                {"turbid, 64 directions", turbid64, turbid64_s},
                {"sweep 0.5 m, 64 dirs (canopy)", sweep_light, sweep_s},
                {"sweep 0.25 m, 64 dirs", sweep_fine, sweep_fine_s},
                {"sweep 0.4 m, 64 dirs", sweep_coarse, sweep_coarse_s}};
    Agreement best_old, leaf, sweep;
    for (const auto& row : rows) {
      const Agreement a = compare(row.values, truth);
      std::printf("  %-34s MAE %.3f  bias %+.3f  r %.2f  %.1f ms\n", row.name, a.mae, a.bias, a.r,
                  1e3 * row.seconds);
      if (&row.values == &centre) best_old = a;
      if (&row.values == &mid) leaf = a;
      if (&row.values == &sweep_light) sweep = a;
    }
    // The adaptation's default cluster light (the sweep) is nearer the traced leaves than eq. 4.3
    // at the centre (the adaptation's `sky`), and ranks the clusters better than it.
    EXPECT_LT(sweep.mae, best_old.mae) << type;
    EXPECT_GT(sweep.r, 0.7) << type;
    EXPECT_GT(sweep.r, best_old.r) << type;
    // The leaf light is nearer the traced leaves than eq. 4.3 at the centre, and ranks the
    // clusters as they do.
    EXPECT_LT(leaf.mae, best_old.mae) << type;
    EXPECT_GT(leaf.r, 0.8) << type;
  }
}

}  // namespace
}  // namespace fspm::environment
