// Core tree graph throughput for a 1-million-node tree: build, traversal, text and binary I/O.
// Items are nodes, so Google Benchmark reports nodes per second.
#include <benchmark/benchmark.h>

#include <random>
#include <sstream>

#include "fspm/binary_tree_format.hpp"
#include "fspm/text_tree_format.hpp"
#include "fspm/tree_graph.hpp"
#include "fspm/tree_traversal.hpp"

namespace {

constexpr std::size_t kNodes = 1'000'000;

// A plant-like tree: each node continues its axis with probability 0.9, branches otherwise.
fspm::TreeGraph build_tree(std::size_t n) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  fspm::TreeGraph t;
  t.reserve(n);
  fspm::NodeData d;
  d.end = {0, 0, 1};
  d.radius = 0.1;
  t.add_node(fspm::kNoNode, d);
  for (std::size_t i = 1; i < n; ++i) {
    const auto parent = static_cast<fspm::NodeId>(u(rng) < 0.9 ? i - 1 : u(rng) * i);
    d.start = t.end(parent);
    d.end = d.start + Eigen::Vector3d(u(rng) - 0.5, u(rng) - 0.5, 1.0);
    d.birth_time = static_cast<double>(i);
    t.add_node(parent, d);
  }
  return t;
}

const fspm::TreeGraph& shared_tree() {
  static const fspm::TreeGraph t = build_tree(kNodes);
  return t;
}

void BM_TreeBuild(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(build_tree(kNodes));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreeBuild)->Unit(benchmark::kMillisecond);

void BM_TreePreorder(benchmark::State& state) {
  const auto& t = shared_tree();
  for (auto _ : state) benchmark::DoNotOptimize(fspm::preorder(t));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreePreorder)->Unit(benchmark::kMillisecond);

void BM_TreeTextWrite(benchmark::State& state) {
  const auto& t = shared_tree();
  for (auto _ : state) {
    std::ostringstream out;
    fspm::write_tree_text(t, out);
    benchmark::DoNotOptimize(out.tellp());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreeTextWrite)->Unit(benchmark::kMillisecond);

void BM_TreeTextRead(benchmark::State& state) {
  std::ostringstream out;
  fspm::write_tree_text(shared_tree(), out);
  const std::string text = out.str();
  for (auto _ : state) {
    std::istringstream in(text);
    benchmark::DoNotOptimize(fspm::read_tree_text(in, "bench"));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreeTextRead)->Unit(benchmark::kMillisecond);

void BM_TreeBinaryWrite(benchmark::State& state) {
  const auto& t = shared_tree();
  for (auto _ : state) {
    std::ostringstream out;
    fspm::write_tree_binary(t, out);
    benchmark::DoNotOptimize(out.tellp());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreeBinaryWrite)->Unit(benchmark::kMillisecond);

void BM_TreeBinaryRead(benchmark::State& state) {
  std::ostringstream out;
  fspm::write_tree_binary(shared_tree(), out);
  const std::string bytes = out.str();
  for (auto _ : state) {
    std::istringstream in(bytes);
    benchmark::DoNotOptimize(fspm::read_tree_binary(in, "bench"));
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kNodes));
}
BENCHMARK(BM_TreeBinaryRead)->Unit(benchmark::kMillisecond);

}  // namespace
