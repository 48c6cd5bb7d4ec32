// Mesh generation throughput (goal: >= 20 million triangles per second on one core) and binary
// glTF export of a 1-million-triangle tree (goal: < 0.5 s).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <Eigen/Geometry>

#include <cmath>
#include <filesystem>
#include <random>

#include "fspm/tree_graph.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
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

// Jaeger 3.1.2: mesh each substructure once and place it by transforms. Represented triangles
// per second counts every instance's triangles (what the explicit path has to generate).
void BM_InstancedMeshCompressedPlant(benchmark::State& state) {
  const auto tree = fspm::greenlab::reconstruct_instanced(leeuwenberg_plant(), {});
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
      fspm::greenlab::reconstruct_instanced(leeuwenberg_plant(), {}));
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("fspm_inst_bench_" + std::to_string(::getpid()) + ".glb"))
                               .string();
  for (auto _ : state) fspm::graphics::write_glb(mesh, path);
  state.counters["bytes"] = static_cast<double>(std::filesystem::file_size(path));
  std::filesystem::remove(path);
  state.counters["represented_triangles"] = static_cast<double>(mesh.triangle_count());
}
BENCHMARK(BM_InstancedGlbExport)->Unit(benchmark::kMillisecond)->UseRealTime();

// Per-instance level of detail: the choice for 10 000 plants on a 100 x 100 grid (5 m apart),
// seen from one corner at 1.7 m above ground looking across the grid (frustum test, expression 2,
// pruning share and jitter per plant, then the instance list); the triangles drawn against all
// plants at their finest.
void BM_SelectLod(benchmark::State& state) {
  namespace g = fspm::graphics;
  g::MeshOptions fine;
  fine.leaves = true;
  const TreeGraph tree = random_tree(6, 5, 7);
  std::vector<g::TriangleMesh> resolutions;
  for (const auto& [edge, sides] : {std::pair{0.01, 16}, std::pair{0.04, 6}, std::pair{0.16, 3}}) {
    g::MeshOptions o = fine;
    o.edge_length_m = edge;
    o.max_sides = sides;
    resolutions.push_back(g::mesh_tree(tree, o));
  }
  g::LodScene scene;
  g::LodOptions lod;
  lod.max_distance_m = 200.0;
  lod.prune_distance_m = 25.0;
  scene.plants.push_back(g::make_lod_plant(resolutions, lod, 1));
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      g::PartPlacement p;
      p.translation =
          Eigen::Vector3f(5.0f * static_cast<float>(i), 5.0f * static_cast<float>(j), 0);
      scene.placements.push_back(p);
    }
  }
  // gluPerspective(60 degrees, 16:10, 0.1, 2000) times a look-at from (-10, -10, 1.7) along
  // the grid's diagonal.
  const Eigen::Vector3d eye(-10, -10, 1.7);
  const Eigen::Vector3d back = -Eigen::Vector3d(1, 1, 0).normalized();
  const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(back).normalized();
  const Eigen::Vector3d up = back.cross(right);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = back.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = -back.dot(eye);
  const double f = 1.0 / std::tan(3.141592653589793 / 6.0), n = 0.1, far = 2000.0;
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = f / 1.6;
  proj(1, 1) = f;
  proj(2, 2) = (far + n) / (n - far);
  proj(2, 3) = 2.0 * far * n / (n - far);
  proj(3, 2) = -1.0;
  std::size_t triangles = 0;
  for (auto _ : state) {
    const auto instances = g::lod_instances(scene, g::select_lod(scene, eye, proj * view, lod));
    triangles = g::lod_triangle_count(scene, instances);
    benchmark::DoNotOptimize(instances.data());
  }
  state.counters["plants"] = static_cast<double>(scene.placements.size());
  state.counters["triangles_drawn"] = static_cast<double>(triangles);
  state.counters["triangles_finest"] =
      static_cast<double>(resolutions.front().triangle_count() * scene.placements.size());
}
BENCHMARK(BM_SelectLod)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
