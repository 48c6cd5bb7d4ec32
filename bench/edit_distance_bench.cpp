// Constrained edit distance between two plant-like random trees of 2 000 and 4 000 nodes
// (goals: < 0.3 s and < 1.5 s on one core). Peak memory is the process's maximum
// resident set size (run one benchmark per process, --benchmark_filter, for a per-case figure).
#include <benchmark/benchmark.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fspm/constrained_edit_distance.hpp"

namespace {

// Axes of internodes: each step extends a random growing tip by one internode and, with
// probability 0.3, starts a lateral axis of the next order there; tips stop with probability
// 0.02. With `leafy`, each new internode also bears one or two leaves (nodes of organ kind leaf),
// so nodes have up to four children. Radii follow the pipe model, lengths shrink with order.
fspm::TreeGraph plant_like_tree(std::size_t n, std::uint64_t seed, bool leafy = false) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  fspm::TreeGraph t;
  t.reserve(n);
  fspm::NodeData root;
  root.length = 0.3;
  t.add_node(fspm::kNoNode, root);
  std::vector<fspm::NodeId> tips{0};
  while (t.size() < n) {
    const std::size_t k = std::uniform_int_distribution<std::size_t>(0, tips.size() - 1)(rng);
    const fspm::NodeId v = tips[k];
    fspm::NodeData d;
    d.order = t.order(v);
    d.length = (0.05 + 0.25 * u(rng)) / (1.0 + d.order);
    tips[k] = t.add_node(v, d);
    if (leafy) {
      const int leaves = u(rng) < 0.5 ? 1 : 2;
      for (int l = 0; l < leaves && t.size() < n; ++l) {
        fspm::NodeData leaf;
        leaf.kind = fspm::OrganKind::kLeaf;
        leaf.order = d.order;
        leaf.length = 0.05 + 0.05 * u(rng);
        t.add_node(tips[k], leaf);
      }
    }
    if (t.size() < n && u(rng) < 0.3) {
      d.order = static_cast<std::uint16_t>(d.order + 1);
      d.length = (0.05 + 0.25 * u(rng)) / (1.0 + d.order);
      tips.push_back(t.add_node(v, d));
    }
    if (tips.size() > 1 && u(rng) < 0.02) {
      tips[k] = tips.back();
      tips.pop_back();
    }
  }
  std::vector<double> r2(n, 0.0);
  for (std::size_t v = n; v-- > 0;) {
    if (t.is_tip(static_cast<fspm::NodeId>(v))) r2[v] = 1e-6;
    t.set_radius(static_cast<fspm::NodeId>(v), std::sqrt(r2[v]));
    if (v > 0) r2[t.parent(static_cast<fspm::NodeId>(v))] += r2[v];
  }
  return t;
}

double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

void run(benchmark::State& state, fspm::EditCostKind cost, bool mapping,
         fspm::AssignmentSolver solver = fspm::AssignmentSolver::kHungarian, bool leafy = false) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const fspm::TreeGraph a = plant_like_tree(n, 1, leafy), b = plant_like_tree(n, 2, leafy);
  fspm::EditDistanceOptions opt;
  opt.cost = cost;
  opt.with_mapping = mapping;
  opt.solver = solver;
  double d = 0.0;
  for (auto _ : state) {
    d = fspm::constrained_edit_distance(a, b, opt).distance;
    benchmark::DoNotOptimize(d);
  }
  std::size_t tips = 0, max_children = 0;
  for (fspm::NodeId v = 0; v < a.size(); ++v) {
    tips += a.is_tip(v) ? 1 : 0;
    max_children = std::max(max_children, a.child_count(v));
  }
  state.counters["tips_a"] = static_cast<double>(tips);
  state.counters["max_children_a"] = static_cast<double>(max_children);
  state.counters["distance"] = d;
  state.counters["peak_rss_MB"] = peak_rss_mb();
}

void BM_EditDistanceStandardized(benchmark::State& s) {
  run(s, fspm::EditCostKind::kStandardized, false);
}
void BM_EditDistanceTopological(benchmark::State& s) {
  run(s, fspm::EditCostKind::kTopological, false);
}
void BM_EditDistanceStandardizedWithMapping(benchmark::State& s) {
  run(s, fspm::EditCostKind::kStandardized, true);
}
void BM_EditDistanceStandardizedMinCostFlow(benchmark::State& s) {
  run(s, fspm::EditCostKind::kStandardized, false, fspm::AssignmentSolver::kMinCostFlow);
}

void BM_EditDistanceStandardizedLeafy(benchmark::State& s) {
  run(s, fspm::EditCostKind::kStandardized, false, fspm::AssignmentSolver::kHungarian, true);
}

BENCHMARK(BM_EditDistanceStandardized)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditDistanceTopological)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditDistanceStandardizedWithMapping)
    ->Arg(2000)
    ->Arg(4000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditDistanceStandardizedLeafy)->Arg(2000)->Arg(4000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EditDistanceStandardizedMinCostFlow)->Arg(2000)->Unit(benchmark::kMillisecond);

}  // namespace
