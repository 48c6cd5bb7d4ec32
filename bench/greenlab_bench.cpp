// GreenLab on a 50-cycle tree of the size of Jaeger et al. (2010) Table 1, last row (1.8 million
// components): compressed-graph generation time, compression ratio against our binary .treeb
// explicit tree, and reconstruction speed in components (internodes + leaves) per second.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_tree.hpp"
#include "fspm/line_tree.hpp"
#include "fspm/tree_file.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"

namespace {

using namespace fspm;

// The example of the source tree, wherever the benchmark is started from.
greenlab::PlantParams table1_params() {
  return greenlab::read_plant_params(std::string(FSPM_SOURCE_DIR) +
                                     "/examples/greenlab/table1_tree.toml");
}

void BM_GreenlabSimulateTable1(benchmark::State& state) {
  const greenlab::PlantParams p = table1_params();
  std::uint64_t metamers = 0;
  std::size_t records = 0;
  for (auto _ : state) {
    CompressedTreeGraph g = greenlab::simulate_compressed(p);
    metamers = g.expanded_size();
    records = g.size();
    benchmark::DoNotOptimize(g);
  }
  state.counters["records"] = static_cast<double>(records);
  state.counters["metamers"] = static_cast<double>(metamers);
}
BENCHMARK(BM_GreenlabSimulateTable1)->Unit(benchmark::kMillisecond);

void BM_GreenlabReconstructTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  for (auto _ : state) {
    TreeGraph t = greenlab::reconstruct(g, {}, &st);
    benchmark::DoNotOptimize(t);
  }
  state.counters["components"] = static_cast<double>(st.components());
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GreenlabReconstructTable1)->Unit(benchmark::kMillisecond);

// The same into one reused TreeGraph (reconstruct_into): what a growth animation pays per frame,
// without the allocation and page faults of a fresh 200 MB graph.
void BM_GreenlabReconstructReuseTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  TreeGraph t;
  greenlab::reconstruct_into(g, {}, t, &st);
  for (auto _ : state) {
    greenlab::reconstruct_into(g, {}, t, &st);
    benchmark::DoNotOptimize(t.size());
    benchmark::ClobberMemory();
  }
  state.counters["components"] = static_cast<double>(st.components());
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["bytes_per_node"] = 117.0;
}
BENCHMARK(BM_GreenlabReconstructReuseTable1)->Unit(benchmark::kMillisecond);

// The ceiling the machine puts on any explicit reconstruction: only storing the bytes of that
// TreeGraph (117 per node, every node of the tree) into an already-touched buffer, with memset.
// Components per second at this rate are the most an explicit TreeGraph build can reach here.
void BM_GreenlabReconstructWriteBound(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  const TreeGraph t = greenlab::reconstruct(g, {}, &st);
  std::vector<unsigned char> bytes(t.size() * 117, 1);
  unsigned char value = 0;
  for (auto _ : state) {
    std::memset(bytes.data(), ++value, bytes.size());
    benchmark::DoNotOptimize(bytes.data());
    benchmark::ClobberMemory();
  }
  state.counters["megabytes"] = static_cast<double>(bytes.size()) / 1e6;
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GreenlabReconstructWriteBound)->Unit(benchmark::kMillisecond);

// The explicit plant as a LineTree (single precision, 45 bytes per component): axes without
// orientation-dependent effects are walked once and copied by rigid transforms.
void BM_GreenlabReconstructLinesTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  for (auto _ : state) {
    LineTree lines = greenlab::reconstruct_lines(g, {}, &st);
    benchmark::DoNotOptimize(lines.size());
    benchmark::ClobberMemory();
  }
  state.counters["components"] = static_cast<double>(st.components());
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GreenlabReconstructLinesTable1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_GreenlabReconstructLinesReuseTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  LineTree lines;
  greenlab::reconstruct_lines_into(g, {}, lines, &st);
  for (auto _ : state) {
    greenlab::reconstruct_lines_into(g, {}, lines, &st);
    benchmark::DoNotOptimize(lines.size());
    benchmark::ClobberMemory();
  }
  state.counters["components"] = static_cast<double>(st.components());
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["bytes_per_node"] = static_cast<double>(LineTree::kBytesPerRecord);
}
BENCHMARK(BM_GreenlabReconstructLinesReuseTable1)->Unit(benchmark::kMillisecond)->UseRealTime();

// What fresh memory costs: a new buffer of the LineTree's size (45 bytes per record) written
// once, page faults and the kernel's zeroing included. A reconstruction into a new LineTree pays
// at least this; reconstruct_lines_into a reused one does not.
void BM_GreenlabLinesFreshWriteBound(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  const LineTree lines = greenlab::reconstruct_lines(g, {}, &st);
  const std::size_t bytes = lines.size() * LineTree::kBytesPerRecord;
  for (auto _ : state) {
    std::vector<unsigned char> buffer;
    buffer.reserve(bytes);
    std::memset(buffer.data(), 1, bytes);
    benchmark::DoNotOptimize(buffer.data());
    benchmark::ClobberMemory();
  }
  state.counters["megabytes"] = static_cast<double>(bytes) / 1e6;
  state.counters["components_per_s"] = benchmark::Counter(
      static_cast<double>(st.components()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GreenlabLinesFreshWriteBound)->Unit(benchmark::kMillisecond);

// Wall-clock seconds: the line reconstruction copies its prototypes on every core (TBB), so the
// calling thread's CPU time would leave most of the work out.
double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The distance to the memory bound, measured in the same run: each iteration builds the output
// and then memsets a buffer (touched beforehand) of the same bytes, one after the other, so a
// noisy machine slows both alike. Iteration time is the build's wall time; ratio_to_memset is
// the build's total over the memset's (1 = as fast as only storing the output with one core).
template <class Build>
void against_memset(benchmark::State& state, std::size_t bytes, std::uint64_t components,
                    Build build) {
  std::vector<unsigned char> buffer(bytes, 1);
  unsigned char value = 0;
  double build_s = 0.0, memset_s = 0.0;
  for (auto _ : state) {
    const double t0 = wall_seconds();
    build();
    const double t1 = wall_seconds();
    std::memset(buffer.data(), ++value, bytes);
    benchmark::DoNotOptimize(buffer.data());
    benchmark::ClobberMemory();
    const double t2 = wall_seconds();
    build_s += t1 - t0;
    memset_s += t2 - t1;
    state.SetIterationTime(t1 - t0);
  }
  const double n = static_cast<double>(components) * static_cast<double>(state.iterations());
  state.counters["components"] = static_cast<double>(components);
  state.counters["megabytes"] = static_cast<double>(bytes) / 1e6;
  state.counters["M_components_per_s"] = n / build_s / 1e6;
  state.counters["memset_M_components_per_s"] = n / memset_s / 1e6;
  state.counters["ratio_to_memset"] = build_s / memset_s;
}

// Explicit reconstruction into a reused LineTree (45 bytes a record) against a memset of its
// records' bytes.
void BM_GreenlabLinesVsMemsetTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  LineTree lines;
  greenlab::reconstruct_lines_into(g, {}, lines, &st);
  against_memset(state, lines.size() * LineTree::kBytesPerRecord, st.components(), [&] {
    greenlab::reconstruct_lines_into(g, {}, lines, &st);
    benchmark::DoNotOptimize(lines.size());
    benchmark::ClobberMemory();
  });
}
BENCHMARK(BM_GreenlabLinesVsMemsetTable1)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(20);

// Explicit reconstruction into a reused TreeGraph (117 bytes a node) against a memset of its
// nodes' bytes.
void BM_GreenlabTreeGraphVsMemsetTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  greenlab::ReconstructionStats st;
  TreeGraph t;
  greenlab::reconstruct_into(g, {}, t, &st);
  against_memset(
      state, static_cast<std::size_t>(static_cast<double>(t.size()) * TreeGraph::bytes_per_node(0)),
      st.components(), [&] {
        greenlab::reconstruct_into(g, {}, t, &st);
        benchmark::DoNotOptimize(t.size());
        benchmark::ClobberMemory();
      });
}
BENCHMARK(BM_GreenlabTreeGraphVsMemsetTable1)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(10);

// Internodes and leaves the instanced plant stands for: each prototype's own plus its children's
// (reconstruct_instanced numbers children after their parents).
std::uint64_t represented_components(const InstancedTree& tree) {
  std::vector<std::uint64_t> total(tree.prototypes.size(), 0);
  for (std::size_t i = tree.prototypes.size(); i-- > 0;) {
    const InstancedTree::Prototype& p = tree.prototypes[i];
    for (const OrganKind k : p.geometry.kinds()) {
      total[i] += k == OrganKind::kInternode || k == OrganKind::kLeaf ? 1 : 0;
    }
    for (const InstancedTree::Child& c : p.children) total[i] += total[c.prototype];
  }
  return total.empty() ? 0 : total[0];
}

void BM_GreenlabInstancedTable1(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  InstancedTree plant;
  for (auto _ : state) {
    plant = greenlab::reconstruct_instanced(g, {});
    benchmark::DoNotOptimize(plant);
  }
  const std::uint64_t components = represented_components(plant);
  state.counters["components"] = static_cast<double>(components);
  state.counters["prototypes"] = static_cast<double>(plant.prototypes.size());
  state.counters["components_per_s"] =
      benchmark::Counter(static_cast<double>(components) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GreenlabInstancedTable1)->Unit(benchmark::kMillisecond);

// Bytes of the explicit tree in .treeb over bytes of the .ctree (anchor: Jaeger Table 1,
// 65.7 MB of line tree for a 96.7 KB graph, about 680x).
void BM_GreenlabCompressionRatio(benchmark::State& state) {
  const CompressedTreeGraph g = greenlab::simulate_compressed(table1_params());
  const auto dir = std::filesystem::temp_directory_path();
  const std::string treeb = (dir / "fspm_greenlab_bench.treeb").string();
  const std::string ctree = (dir / "fspm_greenlab_bench.ctree").string();
  double ratio = 0.0;
  std::uintmax_t treeb_bytes = 0;
  std::uintmax_t ctree_bytes = 0;
  for (auto _ : state) {
    write_tree_file(greenlab::reconstruct(g, {}), treeb);
    write_ctree_file(g, ctree);
    treeb_bytes = std::filesystem::file_size(treeb);
    ctree_bytes = std::filesystem::file_size(ctree);
    ratio = static_cast<double>(treeb_bytes) / static_cast<double>(ctree_bytes);
  }
  std::filesystem::remove(treeb);
  std::filesystem::remove(ctree);
  state.counters["treeb_bytes"] = static_cast<double>(treeb_bytes);
  state.counters["ctree_bytes"] = static_cast<double>(ctree_bytes);
  state.counters["ratio"] = ratio;
}
BENCHMARK(BM_GreenlabCompressionRatio)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
