// Light of every leaf cluster of a 30-year type-A tree (the default growth, about 3 000 clusters)
// through the crown as turbid media: the relative sky light the growth model records, and the
// PAR of a whole clear day at a site (goal: under 50 ms on one core).
#include <benchmark/benchmark.h>

#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/daylight.hpp"
#include "environment/growth_model.hpp"

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

}  // namespace
