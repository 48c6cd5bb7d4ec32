// Developmental stages (Pirk chapter 5): the time to compute one stage, and the analysis, for
// trees of about 2 500, 11 000 and 43 000 branches (preset A grown 20, 30 and 43 years; the last
// has 43 217 internodes and 12 236 leaf clusters, the size of Pirk's largest tree) and 32 767 and
// 65 535 branches (ABOP eq. 1.9 at n = 15 and 16, with widths and unequal branch angles). Pirk
// Table 5.2: 13.0 ms for 3 813 branches, 49.1 ms for 10 623, 76.4 ms for 43 466 ("model" time).
// Goal: under 1 ms for 43 000 branches on one core, so that a slider moves at display rate.
#include <benchmark/benchmark.h>

#include <map>

#include "environment/growth_model.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/turtle.hpp"
#include "stages/developmental_model.hpp"

namespace {

using fspm::TreeGraph;

// Arg < 100: preset A grown that many years; otherwise eq. 1.9 derived Arg - 100 steps.
const TreeGraph& tree_for(int arg) {
  static std::map<int, TreeGraph> trees;
  auto it = trees.find(arg);
  if (it != trees.end()) return it->second;
  TreeGraph t;
  if (arg < 100) {
    fspm::environment::GrowthParams p = fspm::environment::growth_preset("A");
    p.years = arg;
    t = fspm::environment::grow_tree(p).tree;
  } else {
    using namespace fspm::lsystem;
    const LSystem sys = parse_lsystem(
        "#define R 1.456\nAxiom: A(1)\nA(s) --> !(s/10)F(s)[+(30)A(s/R)][-(40)/(90)A(s/R)]\n");
    DeriveOptions options;
    options.steps = arg - 100;
    TurtleSettings view;
    view.line_width_unit = LineWidthUnit::kModel;
    t = interpret(derive(sys, options), sys.symbols, view).tree;
  }
  return trees.emplace(arg, std::move(t)).first->second;
}

void counters(benchmark::State& state, const TreeGraph& t) {
  std::size_t branches = 0;
  for (fspm::NodeId i = 0; i < t.size(); ++i) {
    branches += t.kind(i) == fspm::OrganKind::kInternode;
  }
  state.counters["branches"] = static_cast<double>(branches);
}

// Args: tree (as tree_for), stage time in percent.
void BM_Stage(benchmark::State& state) {
  const TreeGraph& t = tree_for(static_cast<int>(state.range(0)));
  const fspm::stages::DevelopmentalModel model(t);
  const double at = static_cast<double>(state.range(1)) / 100.0;
  TreeGraph out;
  for (auto _ : state) {
    model.stage(at, out);  // reused, as a viewer's slider would
    benchmark::DoNotOptimize(out.size());
  }
  counters(state, t);
  state.counters["stage_nodes"] = static_cast<double>(out.size());
}
BENCHMARK(BM_Stage)
    ->Args({20, 100})
    ->Args({30, 50})
    ->Args({30, 90})
    ->Args({30, 100})
    ->Args({43, 90})
    ->Args({43, 100})
    ->Args({115, 90})
    ->Args({115, 100})
    ->Args({116, 90})
    ->Args({116, 100})
    ->Unit(benchmark::kMillisecond);

// A slider drawn from t = 0.01 to 1 in 100 steps, one stage each into the same tree graph: the
// time per stage a user sees on average (most stages hold far fewer nodes than the last).
void BM_StageSlider(benchmark::State& state) {
  const TreeGraph& t = tree_for(static_cast<int>(state.range(0)));
  const fspm::stages::DevelopmentalModel model(t);
  constexpr int kSteps = 100;
  TreeGraph out;
  std::size_t nodes = 0;
  for (auto _ : state) {
    nodes = 0;
    for (int s = 1; s <= kSteps; ++s) {
      model.stage(static_cast<double>(s) / kSteps, out);
      nodes += out.size();
    }
    benchmark::DoNotOptimize(nodes);
  }
  counters(state, t);
  state.counters["mean_stage_nodes"] = static_cast<double>(nodes) / kSteps;
  state.counters["stages"] = kSteps;  // the time shown is for all of them
}
BENCHMARK(BM_StageSlider)->Arg(43)->Unit(benchmark::kMillisecond);

// Peer in the same run: writing the given tree's nodes into a reused TreeGraph, node by node
// (TreeGraph::Appender, as a stage does), with nothing computed. A stage that writes its nodes as a
// TreeGraph cannot take less; the ratio BM_Stage / this peer shows how much of a stage is the model
// rather than the writing.
void BM_StageCopyPeer(benchmark::State& state) {
  const TreeGraph& t = tree_for(static_cast<int>(state.range(0)));
  TreeGraph out;
  for (auto _ : state) {
    out.clear_keep_capacity();
    TreeGraph::Appender append(out, t.size());
    for (fspm::NodeId i = 0; i < t.size(); ++i) append.add(t.parent(i), t.data(i));
    append.finish();
    benchmark::DoNotOptimize(out.size());
  }
  counters(state, t);
  state.counters["stage_nodes"] = static_cast<double>(out.size());
}
BENCHMARK(BM_StageCopyPeer)->Arg(43)->Unit(benchmark::kMillisecond);

// Args: years of preset A grown with the pipes of its shed branches kept (keep_shed_pipes),
// stage time in percent; the model reconstructs the shed branches (StagesParams::shed) and
// chooses growth profiles by chain.
void BM_StageShed(benchmark::State& state) {
  static std::map<int, TreeGraph> trees;
  const int years = static_cast<int>(state.range(0));
  if (!trees.contains(years)) {
    fspm::environment::GrowthParams p = fspm::environment::growth_preset("A");
    p.years = years;
    p.keep_shed_pipes = true;
    trees.emplace(years, fspm::environment::grow_tree(p).tree);
  }
  const TreeGraph& t = trees.at(years);
  fspm::stages::StagesParams params;
  params.shed.enabled = true;
  params.profiles = fspm::stages::ProfileChoice::kByChain;
  const fspm::stages::DevelopmentalModel model(t, params);
  const double at = static_cast<double>(state.range(1)) / 100.0;
  TreeGraph out;
  for (auto _ : state) {
    model.stage(at, out);
    benchmark::DoNotOptimize(out.size());
  }
  counters(state, t);
  state.counters["stage_nodes"] = static_cast<double>(out.size());
  state.counters["shed_branches"] = static_cast<double>(model.shed_branch_count());
}
BENCHMARK(BM_StageShed)
    ->Args({30, 67})
    ->Args({30, 100})
    ->Args({43, 90})
    ->Args({43, 100})
    ->Unit(benchmark::kMillisecond);

void BM_StagesAnalysis(benchmark::State& state) {
  const TreeGraph& t = tree_for(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const fspm::stages::DevelopmentalModel model(t);
    benchmark::DoNotOptimize(model.chain_count());
  }
  counters(state, t);
}
BENCHMARK(BM_StagesAnalysis)->Arg(30)->Arg(115)->Arg(116)->Unit(benchmark::kMillisecond);

}  // namespace
