// Light of every leaf cluster of a 30-year type-A tree (the default growth, about 3 000 clusters)
// through the crown as turbid media: the relative sky light the growth model records, and the
// PAR of a whole clear day at a site (goal: under 50 ms on one core); and the time of the
// ray-traced yardstick (tests/environment/leaf_ray_tracer.hpp) beside the turbid medium's.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/canopy_summary.hpp"
#include "environment/daylight.hpp"
#include "environment/growth_model.hpp"
#include "environment/leaf_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/sky_distribution.hpp"
#include "tests/environment/leaf_ray_tracer.hpp"

namespace {

using namespace fspm::environment;

const GrowthResult& tree_a30() {
  static const GrowthResult g = [] {
    GrowthParams p = growth_preset("A");
    p.years = 30;
    return grow_tree(p);
  }();
  return g;
}

Scene leaf_sky() {
  Scene s;
  s.sky.directions = GrowthParams{}.light_directions;  // as the growth model records it
  s.sky.significance = Sky{}.significance;
  return s;
}

// Arg: voxel size in cm (0: every cluster's sphere followed exactly).
void BM_CanopyLeafLight30YearA(benchmark::State& state) {
  const GrowthResult& g = tree_a30();
  for (auto _ : state) {
    const CanopyLight light(leaf_sky(), g.cluster_spheres, 0.01 * state.range(0));
    auto out = light.evaluate_clusters();
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["clusters"] = static_cast<double>(g.cluster_spheres.size());
}
BENCHMARK(BM_CanopyLeafLight30YearA)->Arg(0)->Arg(10)->Arg(15)->Unit(benchmark::kMillisecond);

// A clear 21 June at 45 N, 0-24 h in 15-minute steps, PAR at every cluster's centre.
void BM_CanopyDaylight30YearA(benchmark::State& state) {  // arg: voxel size in cm
  const GrowthResult& g = tree_a30();
  RealSky sky;
  sky.site = {45.0, 7.0, 300.0, 1.0};
  sky.date = {2024, 6, 21};
  std::vector<Eigen::Vector3d> centres;
  for (const Sphere& c : g.cluster_spheres) centres.push_back(c.center);
  for (auto _ : state) {
    const CanopyLight light(leaf_sky(), g.cluster_spheres, 0.01 * state.range(0));
    auto out = daylight_at(light, sky, centres);
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["clusters"] = static_cast<double>(g.cluster_spheres.size());
}
BENCHMARK(BM_CanopyDaylight30YearA)->Arg(0)->Arg(10)->Arg(15)->Unit(benchmark::kMillisecond);

// The same day through the crown swept in voxels (daylight_through_voxels, CanopySweep; arg: voxel
// size in cm): one sweep per sky direction and per step with the sun up.
void BM_CanopyDaylightSweep30YearA(benchmark::State& state) {
  const GrowthResult& g = tree_a30();
  RealSky sky;
  sky.site = {45.0, 7.0, 300.0, 1.0};
  sky.date = {2024, 6, 21};
  std::vector<Eigen::Vector3d> centres;
  for (const Sphere& c : g.cluster_spheres) centres.push_back(c.center);
  for (auto _ : state) {
    auto out = daylight_through_voxels(g.cluster_spheres, leaf_sky(), sky, centres,
                                       0.01 * static_cast<double>(state.range(0)));
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["clusters"] = static_cast<double>(g.cluster_spheres.size());
}
BENCHMARK(BM_CanopyDaylightSweep30YearA)->Arg(50)->Arg(25)->Unit(benchmark::kMillisecond);

// Growth's leaf PAR under a real sky (record_leaf_par: the crown swept in 0.5 m voxels, 64 diffuse
// directions and every sun position of a clear 21 June at 45 N) and the canopy light summary
// (sunlit and shaded leaf area, LIE, STAR, absorbed PAR per cluster) under the same sky.
Scene real_day_scene() {
  RealSky day;
  day.site = {45.0, 7.0, 300.0, 1.0};
  day.date = {2024, 6, 21};
  Scene s = leaf_sky();
  apply_sky_distribution(s.sky, std::make_shared<const SkyDistribution>(sky_distribution(day)));
  return s;
}

void BM_GrownLeafPar30YearA(benchmark::State& state) {
  const GrowthResult& g = tree_a30();
  const Scene scene = real_day_scene();
  fspm::TreeGraph tree = g.tree;
  std::vector<std::uint32_t> sphere_of;
  const std::vector<Sphere> clusters = leaf_spheres(tree, sphere_of);
  for (auto _ : state) {
    record_leaf_par(tree, scene, clusters, sphere_of);
    benchmark::DoNotOptimize(tree.attribute(kParAttribute).data());
  }
  state.counters["clusters"] = static_cast<double>(clusters.size());
}
BENCHMARK(BM_GrownLeafPar30YearA)->Unit(benchmark::kMillisecond);

void BM_CanopyLightSummary30YearA(benchmark::State& state) {
  const GrowthResult& g = tree_a30();
  const Scene scene = real_day_scene();
  for (auto _ : state) {
    const CanopyLightSummary c = summarize_canopy_light(g.cluster_spheres, scene.sky);
    benchmark::DoNotOptimize(c.absorbed_par_mol_day);
  }
  state.counters["clusters"] = static_cast<double>(g.cluster_spheres.size());
}
BENCHMARK(BM_CanopyLightSummary30YearA)->Unit(benchmark::kMillisecond);

// The yardstick: ray tracing the leaves and wood of the 15-year type-A tree (16 leaves and 64 rays
// per cluster), against the turbid medium's light for the same clusters (counter `ratio`).
void BM_LightYardstick15YearA(benchmark::State& state) {
  static const GrowthResult g = [] {
    GrowthParams p = growth_preset("A");
    p.years = 15;
    return grow_tree(p);
  }();
  std::mt19937_64 rng(7);
  std::vector<std::uint32_t> leaf_start;
  std::vector<yardstick::Triangle> tris =
      yardstick::leaf_triangles(g.cluster_spheres, rng, leaf_start);
  yardstick::add_wood(g.tree, tris);
  for (auto _ : state) {
    const yardstick::Bvh bvh(tris);
    auto out = yardstick::traced_light(bvh, tris, leaf_start, 16, 64, rng);
    benchmark::DoNotOptimize(out.data());
  }
  const auto t0 = std::chrono::steady_clock::now();
  constexpr int kRuns = 20;
  for (int k = 0; k < kRuns; ++k) {
    auto lit = CanopyLight(leaf_sky(), g.cluster_spheres).evaluate_clusters();
    benchmark::DoNotOptimize(lit.data());
  }
  const double canopy_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / kRuns;
  // The adaptation's default leaf light (the sweep in 0.5 m voxels, 64 directions).
  Sky sky64;
  sky64.directions = 64;
  const auto sweep = make_leaf_light_model("sweep", sky64);
  std::vector<LightSample> lit(g.cluster_spheres.size());
  const auto t1 = std::chrono::steady_clock::now();
  for (int k = 0; k < kRuns; ++k) {
    sweep->evaluate(g.cluster_spheres, {}, lit);
    benchmark::DoNotOptimize(lit.data());
  }
  const double sweep_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() / kRuns;
  state.counters["clusters"] = static_cast<double>(g.cluster_spheres.size());
  state.counters["canopy_ms"] = 1e3 * canopy_s;
  state.counters["sweep_ms"] = 1e3 * sweep_s;
}
BENCHMARK(BM_LightYardstick15YearA)->Unit(benchmark::kMillisecond);

}  // namespace
