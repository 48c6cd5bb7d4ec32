// L-system throughput. Single core.
//   derive/abop_1_24a/10: ABOP fig. 1.24a, F -> F[+F]F[-F]F, n = 10 (24.4 million modules).
//     Goals: >= 100 million modules/s, <= 16 bytes/module.
//   derive/parametric_tree/20: ABOP eq. 1.9, A(s) -> F(s)[+A(s/R)][-A(s/R)], n = 20
//     (8.4 million modules). Goal: >= 20 million modules/s.
//   interpret/abop_1_24a/N: turtle into a TreeGraph. Goal: >= 20 million modules/s.
//   derive_compressed/abop_1_24a/20 and derive_compressed/parametric_tree/40: the same grammars
//     derived into shared substructures (Jaeger et al. 2010, 2.1.3) at n where no explicit
//     string fits (2.4 * 10^14 and 8.8 * 10^12 modules). Goal: under 1 ms and 1 MB each.
//   derive_instanced/abop_1_24a/N: the same grammar derived into substructures and drawn by
//     instancing (Jaeger 3.1.2; lsystem/instanced_interpretation.hpp), exactly, at n = 12
//     (6 * 10^8 modules) and n = 20 (2.4 * 10^14). Goal: under 1 ms and 1 MB.
//   instanced_mesh/abop_1_24a/12: that drawing with the level of detail of a 1024-pixel picture
//     (substructures under a pixel drawn as one internode), meshed as the renderer takes it.
//     Goal: a picture of the plant in a few seconds (the render itself: docs/BENCHMARKS.md).
// "modules/s" counts the modules of the final string per second of the whole run.
#include <benchmark/benchmark.h>

#include "graphics/instanced_mesh.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/instanced_interpretation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"

namespace {

using namespace fspm::lsystem;

const char* kAbop124a = "Axiom: F\nF --> F[+F]F[-F]F\n";
const char* kParametricTree = "#define R 1.456\nAxiom: A(1)\nA(s) --> F(s)[+A(s/R)][-A(s/R)]\n";

void derive_bench(benchmark::State& state, const char* grammar) {
  const LSystem sys = parse_lsystem(grammar);
  DeriveOptions options;
  options.steps = static_cast<int>(state.range(0));
  std::size_t modules = 0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    Derivation d(sys, options);
    d.run();
    modules = d.string().size();
    bytes = d.string().memory_bytes();
    benchmark::DoNotOptimize(d.string().symbols().data());
  }
  state.counters["modules"] = static_cast<double>(modules);
  state.counters["modules_per_s"] =
      benchmark::Counter(static_cast<double>(modules) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["bytes_per_module"] = static_cast<double>(bytes) / static_cast<double>(modules);
}

void BM_DeriveAbop124a(benchmark::State& state) { derive_bench(state, kAbop124a); }
BENCHMARK(BM_DeriveAbop124a)->Name("derive/abop_1_24a")->Arg(10)->Unit(benchmark::kMillisecond);

void BM_DeriveParametricTree(benchmark::State& state) { derive_bench(state, kParametricTree); }
BENCHMARK(BM_DeriveParametricTree)
    ->Name("derive/parametric_tree")
    ->Arg(20)
    ->Unit(benchmark::kMillisecond);

void derive_compressed_bench(benchmark::State& state, const char* grammar) {
  const LSystem sys = parse_lsystem(grammar);
  DeriveOptions options;
  options.steps = static_cast<int>(state.range(0));
  SubstructureCounts counts;
  std::size_t nodes = 0, bytes = 0;
  for (auto _ : state) {
    const SubstructureGraph g = derive_substructures(sys, options);
    counts = count_modules(g, sys.symbols.size());
    nodes = g.nodes.size();
    bytes = g.memory_bytes();
    benchmark::DoNotOptimize(counts.modules);
  }
  state.counters["modules"] = static_cast<double>(counts.modules);
  state.counters["graph_nodes"] = static_cast<double>(nodes);
  state.counters["graph_bytes"] = static_cast<double>(bytes);
}

void BM_DeriveCompressedAbop124a(benchmark::State& state) {
  derive_compressed_bench(state, kAbop124a);
}
BENCHMARK(BM_DeriveCompressedAbop124a)
    ->Name("derive_compressed/abop_1_24a")
    ->Arg(20)
    ->Unit(benchmark::kMicrosecond);

void BM_DeriveCompressedParametricTree(benchmark::State& state) {
  derive_compressed_bench(state, kParametricTree);
}
BENCHMARK(BM_DeriveCompressedParametricTree)
    ->Name("derive_compressed/parametric_tree")
    ->Arg(40)
    ->Unit(benchmark::kMicrosecond);

void BM_InterpretAbop124a(benchmark::State& state) {
  const LSystem sys = parse_lsystem(kAbop124a);
  DeriveOptions options;
  options.steps = static_cast<int>(state.range(0));
  const ModuleString s = derive(sys, options);
  TurtleSettings view;
  view.angle_deg = 25.7;
  std::size_t nodes = 0;
  for (auto _ : state) {
    const Interpretation r = interpret(s, sys.symbols, view);
    nodes = r.tree.size();
  }
  state.counters["modules"] = static_cast<double>(s.size());
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["modules_per_s"] =
      benchmark::Counter(static_cast<double>(s.size()) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_InterpretAbop124a)
    ->Name("interpret/abop_1_24a")
    ->Arg(8)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);

const char* kAbop124aView = "angle increment: 25.7\ninitial line width: 2 pixels\n";

void BM_DeriveInstancedAbop124a(benchmark::State& state) {
  const LSystem sys = parse_lsystem(kAbop124a);
  const TurtleSettings view = parse_view(kAbop124aView);
  DeriveOptions options;
  options.steps = static_cast<int>(state.range(0));
  InstancedInterpretation drawn;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const SubstructureGraph g = derive_substructures(sys, options);
    drawn = interpret_instanced(g, sys, view);
    bytes = g.memory_bytes();
    benchmark::DoNotOptimize(drawn.internodes);
  }
  for (const auto& p : drawn.tree.prototypes) {
    bytes += sizeof(p) + p.children.capacity() * sizeof(fspm::InstancedTree::Child) +
             static_cast<std::size_t>(static_cast<double>(p.geometry.size()) *
                                      fspm::TreeGraph::bytes_per_node(1));
  }
  state.counters["segments"] = static_cast<double>(drawn.internodes);
  state.counters["prototypes"] = static_cast<double>(drawn.tree.prototypes.size());
  state.counters["bytes"] = static_cast<double>(bytes);
}
BENCHMARK(BM_DeriveInstancedAbop124a)
    ->Name("derive_instanced/abop_1_24a")
    ->Arg(12)
    ->Arg(20)
    ->Unit(benchmark::kMicrosecond);

void BM_InstancedMeshAbop124a(benchmark::State& state) {
  const LSystem sys = parse_lsystem(kAbop124a);
  const TurtleSettings view = parse_view(kAbop124aView);
  DeriveOptions options;
  options.steps = static_cast<int>(state.range(0));
  std::size_t instances = 0, triangles = 0;
  for (auto _ : state) {
    const SubstructureGraph g = derive_substructures(sys, options);
    InstancedInterpretationOptions lod;
    const InstancedInterpretation exact = interpret_instanced(g, sys, view, lod);
    lod.min_detail = exact.bounds.sizes().maxCoeff() / 1024.0;
    const InstancedInterpretation drawn = interpret_instanced(g, sys, view, lod);
    const fspm::graphics::InstancedMesh mesh = fspm::graphics::mesh_instanced(drawn.tree);
    instances = mesh.instances.size();
    triangles = mesh.triangle_count();
  }
  state.counters["instances"] = static_cast<double>(instances);
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_InstancedMeshAbop124a)
    ->Name("instanced_mesh/abop_1_24a")
    ->Arg(12)
    ->Unit(benchmark::kMillisecond);

}  // namespace
