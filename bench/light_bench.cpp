// Light for 10 000 points among 1 000 leaf clusters with 256 directions (goal: < 1 s on one core;
// brute force would be about 2.6 billion ray-sphere tests).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "environment/light_model.hpp"
#include "environment/sky_occlusion_kernel.hpp"

namespace {

using fspm::environment::LightModel;
using fspm::environment::LightSample;
using fspm::environment::Scene;

Scene crown_scene(int clusters, double significance, int directions = 256) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene s;
  s.sky.directions = directions;
  s.sky.significance = significance;
  for (int i = 0; i < clusters; ++i) {
    const double r = 0.3 + 0.7 * u(rng);
    s.spheres.push_back({{20 * u(rng), 20 * u(rng), 2 + 10 * u(rng)},
                         r,
                         fspm::environment::cluster_translucency(r),
                         false});
  }
  return s;
}

std::vector<Eigen::Vector3d> crown_points(int n) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Eigen::Vector3d> p(n);
  for (auto& x : p) x = {20 * u(rng), 20 * u(rng), 12 * u(rng)};
  return p;
}

// Light at 10 000 points of the crown of `scene`, per iteration.
void light_at_crown_points(benchmark::State& state, const Scene& scene) {
  const LightModel model(scene);
  const auto points = crown_points(10000);
  std::vector<LightSample> out(points.size());
  for (auto _ : state) {
    model.evaluate(points, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(points.size()));
  state.SetLabel("simd " + fspm::environment::sky_occlusion_target());  // FSPM_SIMD_TARGET
}

void BM_Light10kPoints1kClusters(benchmark::State& state) {
  const double significance = state.range(0) == 0 ? 0.0 : 1e-3;
  light_at_crown_points(state, crown_scene(1000, significance));
}
// Arg 1: default shadow-volume cutoff (significance 1e-3); arg 0: no cutoff (exact).
BENCHMARK(BM_Light10kPoints1kClusters)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// The same with 64 directions (the growth model's sky): every cap of a point in one vector sweep.
void BM_Light10kPoints1kClusters64Directions(benchmark::State& state) {
  light_at_crown_points(state, crown_scene(1000, 1e-3, 64));
}
BENCHMARK(BM_Light10kPoints1kClusters64Directions)->Unit(benchmark::kMillisecond);

// The same crown beside a 15 m wall (boxes in closed form, overlaps with clusters sampled finer).
void BM_Light10kPointsBesideWall(benchmark::State& state) {
  Scene s = crown_scene(1000, 1e-3);
  s.boxes.push_back(fspm::environment::Box::wall({-1, -5}, {-1, 25}, 0, 15, 0.3));
  light_at_crown_points(state, s);
}
BENCHMARK(BM_Light10kPointsBesideWall)->Unit(benchmark::kMillisecond);

// The sky-occlusion kernel alone: range(0) directions against range(1) caps of 18-26 degrees
// (narrow, as most cluster caps are), all in one call, in double precision.
void BM_SkyOcclusionKernel(benchmark::State& state) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto unit = [&] {
    const Eigen::Vector3d v(normal(rng), normal(rng), std::abs(normal(rng)) + 1e-9);
    return Eigen::Vector3d(v.normalized());
  };
  const auto n = static_cast<std::size_t>(state.range(0));
  std::vector<double> x(n), y(n), z(n), vis(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d d = unit();
    x[i] = d.x();
    y[i] = d.y();
    z[i] = d.z();
  }
  std::vector<fspm::environment::OccludingCap<double>> caps;
  for (int k = 0; k < state.range(1); ++k) {
    const Eigen::Vector3d a = unit();
    caps.push_back({a.x(), a.y(), a.z(), 0.9 + 0.05 * u(rng), u(rng)});
  }
  for (auto _ : state) {
    std::fill(vis.begin(), vis.end(), 1.0);
    fspm::environment::occlude_by_caps(vis, {x.data(), y.data(), z.data()}, caps);
    benchmark::DoNotOptimize(vis.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0) * state.range(1));
  state.SetLabel("simd " + fspm::environment::sky_occlusion_target());
}
BENCHMARK(BM_SkyOcclusionKernel)->Args({64, 40})->Args({100, 40})->Args({256, 1});

void BM_LightBuildIndex(benchmark::State& state) {
  const Scene s = crown_scene(1000, 1e-3);
  for (auto _ : state) {
    LightModel model(s);
    benchmark::DoNotOptimize(model.index_entries());
  }
}
BENCHMARK(BM_LightBuildIndex)->Unit(benchmark::kMillisecond);

}  // namespace
