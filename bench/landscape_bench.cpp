// Landscapes of thousands of trees (Argudo 2014, chapter 6): placing 10 000 trees on a terrain
// (blue-noise sites, class and plant draws, bilinear heights) and meshing the terrain.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "graphics/heightfield.hpp"
#include "graphics/population.hpp"

namespace g = fspm::graphics;

namespace {

// 129 x 129 samples at 4 m (512 m square), rolling hills up to 60 m.
g::Heightfield hills() {
  g::FloatImage image;
  image.width = image.height = 129;
  for (int j = 0; j < 129; ++j) {
    for (int i = 0; i < 129; ++i) {
      image.values.push_back(
          static_cast<float>(0.5 + 0.25 * std::sin(0.07 * i) * std::cos(0.05 * j) + 0.002 * j));
    }
  }
  return g::Heightfield(image, 4.0, 60.0);
}

fspm::ScenePopulation forest(double count) {
  fspm::ScenePopulation p;
  p.min_distance_m = 3.0;
  p.count = count;
  p.scale_jitter = 0.25;
  fspm::PopulationClass c;
  c.plants = {{"pine.toml", 0.7, {}}, {"oak.toml", 0.3, {}}};
  p.classes.push_back(c);
  return p;
}

void BM_PlaceTrees(benchmark::State& state) {
  const g::Heightfield terrain = hills();
  const fspm::ScenePopulation population = forest(static_cast<double>(state.range(0)));
  std::size_t placed = 0;
  for (auto _ : state) {
    std::mt19937_64 rng(7);
    const auto plants = g::place_population(population, terrain, nullptr, rng);
    placed = plants.size();
    benchmark::DoNotOptimize(plants.data());
  }
  state.counters["trees"] = static_cast<double>(placed);
}
BENCHMARK(BM_PlaceTrees)->Arg(10000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_TerrainMesh(benchmark::State& state) {
  const g::Heightfield terrain = hills();
  std::size_t triangles = 0;
  for (auto _ : state) {
    const g::TriangleMesh mesh = g::heightfield_mesh(terrain, 1);
    triangles = mesh.triangle_count();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_TerrainMesh)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
