// Mesh generation throughput (goal: >= 20 million triangles per second on one core) and binary
// glTF export of a 1-million-triangle tree (goal: < 0.5 s), issue 8 item 7.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <random>

#include "fspm/tree_graph.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"

namespace {

using fspm::NodeId;
using fspm::TreeGraph;

// A seeded random binary tree: `depth` branching levels, `segments` internodes per branch,
// radius shrinking by 0.85 a level, gentle random bends so frames really get transported.
TreeGraph random_tree(int depth, int segments, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> jitter(0.0, 0.08);
  TreeGraph t;
  struct Item {
    NodeId parent;
    Eigen::Vector3d base, dir;
    int level;
    double radius;
  };
  std::vector<Item> stack{
      {fspm::kNoNode, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0, 0.2}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    NodeId last = it.parent;
    Eigen::Vector3d p = it.base, d = it.dir;
    for (int s = 0; s < segments; ++s) {
      d = (d + Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng))).normalized();
      fspm::NodeData nd;
      nd.start = p;
      nd.end = p + 0.3 * std::pow(0.8, it.level) * d;
      nd.radius = it.radius;
      nd.birth_time = it.level + 0.1 * s;
      nd.order = static_cast<std::uint16_t>(it.level);
      last = t.add_node(last, nd);
      p = nd.end;
    }
    if (it.level + 1 < depth) {
      for (int side = -1; side <= 1; side += 2) {
        const Eigen::Vector3d lateral = d.unitOrthogonal();
        stack.push_back(
            {last, p, (d + 0.8 * side * lateral).normalized(), it.level + 1, it.radius * 0.85});
      }
    }
  }
  return t;
}

const TreeGraph& million_triangle_tree() {
  static const TreeGraph tree = random_tree(12, 7, 42);
  return tree;
}

void BM_MeshGeneration(benchmark::State& state) {
  const TreeGraph& tree = million_triangle_tree();
  std::size_t triangles = 0;
  for (auto _ : state) {
    const fspm::graphics::TriangleMesh mesh = fspm::graphics::mesh_tree(tree);
    triangles += mesh.triangle_count();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles / state.iterations());
  state.counters["triangles_per_s"] =
      benchmark::Counter(static_cast<double>(triangles), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MeshGeneration)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_GlbExport(benchmark::State& state) {
  const fspm::graphics::TriangleMesh mesh = fspm::graphics::mesh_tree(million_triangle_tree());
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("fspm_mesh_bench_" + std::to_string(::getpid()) + ".glb"))
                               .string();
  for (auto _ : state) fspm::graphics::write_glb(mesh, path);
  std::filesystem::remove(path);
  state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
  state.counters["MB"] =
      static_cast<double>(mesh.vertex_count() * (32 + 4 * mesh.attributes.size()) +
                          mesh.triangle_count() * 12) /
      1e6;
}
BENCHMARK(BM_GlbExport)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
