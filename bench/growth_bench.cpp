// Self-organizing growth: trees of 10, 20 and 30 years (Pirk Table 4.2 anchor: about 530, 2 500 and
// 9 100 internodes, grown with Open L-systems in 216 ms, 8.9 s and 61.8 s) and the growth rate
// (goal: >= 100 000 internodes/s; Palubicki et al. 2009: 642 000 internodes in 60 s).
#include <benchmark/benchmark.h>

#include "environment/growth_model.hpp"

namespace {

void grow_preset(
    benchmark::State& state, const char* preset, int years,
    fspm::environment::BudLightModel model = fspm::environment::BudLightModel::kShadowGrid) {
  fspm::environment::GrowthParams p = fspm::environment::growth_preset(preset, model);
  p.years = years;
  std::size_t internodes = 0, grown = 0;
  for (auto _ : state) {
    const auto r = fspm::environment::grow_tree(p);
    internodes = r.internodes;
    grown = r.grown;
    benchmark::DoNotOptimize(r.tree.size());
  }
  state.counters["internodes"] = static_cast<double>(internodes);
  state.counters["grown"] = static_cast<double>(grown);
  // Internodes created per second (shed ones included), and those of the final tree.
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(grown));
  state.counters["alive_per_s"] =
      benchmark::Counter(static_cast<double>(internodes) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void BM_GrowPresetA(benchmark::State& state) {
  grow_preset(state, "A", static_cast<int>(state.range(0)));
}
BENCHMARK(BM_GrowPresetA)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_GrowPresetB(benchmark::State& state) {
  grow_preset(state, "B", static_cast<int>(state.range(0)));
}

// Preset A at 30 years with each light model: 0 sky, 1 shadow grid (the default), 2 space
// colonization.
void BM_GrowLightModel(benchmark::State& state) {
  using fspm::environment::BudLightModel;
  const BudLightModel models[] = {BudLightModel::kSky, BudLightModel::kShadowGrid,
                                  BudLightModel::kSpaceColonization};
  grow_preset(state, "A", 30, models[state.range(0)]);
}
BENCHMARK(BM_GrowLightModel)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GrowPresetB)->Arg(10)->Arg(20)->Arg(30)->Unit(benchmark::kMillisecond);

void BM_GrowBesideWall(benchmark::State& state) {
  fspm::environment::GrowthParams p = fspm::environment::growth_preset("B");
  p.years = 20;
  fspm::environment::Scene scene;
  scene.boxes.push_back(fspm::environment::Box::wall({2.5, -20}, {2.5, 20}, 0.0, 6.0, 0.2));
  std::size_t grown = 0;
  for (auto _ : state) {
    const auto r = fspm::environment::grow_tree(p, scene);
    grown = r.grown;
    benchmark::DoNotOptimize(r.tree.size());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(grown));
}
BENCHMARK(BM_GrowBesideWall)->Unit(benchmark::kMillisecond);

}  // namespace
