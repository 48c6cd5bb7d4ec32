// Mesh generation throughput (goal: >= 20 million triangles per second on one core) and binary
// glTF export of a 1-million-triangle tree (goal: < 0.5 s).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <random>

#include "fspm/tree_graph.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/reconstruction.hpp"
#include "greenlab/simulation.hpp"

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

// Leeuwenberg's model (examples/greenlab/leeuwenberg.toml, straightening off so the instanced
// plant is exactly the explicit one) grown 9 cycles: 3^k growth units, about 40 000 metamers.
const fspm::CompressedTreeGraph& leeuwenberg_plant() {
  static const fspm::CompressedTreeGraph graph =
      fspm::greenlab::simulate_compressed(fspm::greenlab::parse_plant_params(R"(
[plant]
cycles = 9
seed = 1

[[age]]
index = 1
duration = 1
next_age = 0
terminal = "flower"
branching_delay = 1
units = [
  { count = 3 },
  { count = 1, axillary = [ { age = 1, count = 3 } ] },
]
leaf_life_span = 2
branching_angle = 40.0
phyllotaxy = 120.0
straightening = 0.0
internode_length = 0.3
internode_radius = 0.02
radius_growth = 0.004
leaf_length = 0.2
)",
                                                                             "leeuwenberg"));
  return graph;
}

fspm::graphics::InstancedTree instanced_tree(fspm::greenlab::InstancedPlant plant) {
  fspm::graphics::InstancedTree tree;
  for (auto& p : plant.prototypes) {
    fspm::graphics::InstancedTree::Prototype q;
    q.geometry = std::move(p.geometry);
    for (const auto& c : p.children) {
      q.children.push_back({c.prototype, c.attach, c.rotation, c.translation});
    }
    tree.prototypes.push_back(std::move(q));
  }
  return tree;
}

// Jaeger 3.1.2: mesh each substructure once and place it by transforms. Represented triangles
// per second counts every instance's triangles (what the explicit path has to generate).
void BM_InstancedMeshCompressedPlant(benchmark::State& state) {
  const auto tree = instanced_tree(fspm::greenlab::reconstruct_instanced(leeuwenberg_plant(), {}));
  std::size_t represented = 0, stored = 0, instances = 0;
  for (auto _ : state) {
    const auto mesh = fspm::graphics::mesh_instanced(tree);
    represented += mesh.triangle_count();
    stored = mesh.stored_triangle_count();
    instances = mesh.instances.size();
    benchmark::DoNotOptimize(mesh.meshes.data());
  }
  state.counters["represented_triangles"] = static_cast<double>(represented / state.iterations());
  state.counters["stored_triangles"] = static_cast<double>(stored);
  state.counters["instances"] = static_cast<double>(instances);
  state.counters["represented_per_s"] =
      benchmark::Counter(static_cast<double>(represented), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_InstancedMeshCompressedPlant)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same plant the explicit way: reconstruct every metamer, then mesh the whole tree.
void BM_ExplicitMeshCompressedPlant(benchmark::State& state) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    const TreeGraph tree = fspm::greenlab::reconstruct(leeuwenberg_plant(), {});
    const auto mesh = fspm::graphics::mesh_tree(tree);
    triangles += mesh.triangle_count();
    benchmark::DoNotOptimize(mesh.positions.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles / state.iterations());
}
BENCHMARK(BM_ExplicitMeshCompressedPlant)->Unit(benchmark::kMillisecond)->UseRealTime();

// Instanced .glb of the plant: each substructure mesh stored once, one node per occurrence.
void BM_InstancedGlbExport(benchmark::State& state) {
  const auto mesh = fspm::graphics::mesh_instanced(
      instanced_tree(fspm::greenlab::reconstruct_instanced(leeuwenberg_plant(), {})));
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("fspm_inst_bench_" + std::to_string(::getpid()) + ".glb"))
                               .string();
  for (auto _ : state) fspm::graphics::write_glb(mesh, path);
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
  state.counters["represented_triangles"] = static_cast<double>(mesh.triangle_count());
}
BENCHMARK(BM_InstancedGlbExport)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
