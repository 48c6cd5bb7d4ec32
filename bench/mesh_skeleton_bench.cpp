// The skeleton of a branch mesh by contraction (Pirk 5.2.1, Au et al. 2008): the analysis time
// (welding, Laplacian contraction, joining, spanning tree, tree graph) for the bark mesh of a
// grown tree written by fspm's tree mesher (separate closed tubes). Arg: years of preset A;
// the counters give the mesh's vertices and the skeleton's internodes. Goal: under one second
// for about 100 000 vertices.
#include <benchmark/benchmark.h>

#include <map>

#include "environment/growth_model.hpp"
#include "graphics/tree_mesher.hpp"
#include "stages/mesh_skeleton.hpp"

namespace {

struct Input {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

const Input& mesh_for(int years) {
  static std::map<int, Input> inputs;
  auto it = inputs.find(years);
  if (it != inputs.end()) return it->second;
  fspm::environment::GrowthParams p = fspm::environment::growth_preset("A");
  p.years = years;
  const fspm::graphics::TriangleMesh m =
      fspm::graphics::mesh_tree(fspm::environment::grow_tree(p).tree);
  Input in;
  for (const Eigen::Vector3f& v : m.positions) in.vertices.push_back(v.cast<double>());
  for (const auto& t : m.triangles) in.faces.push_back({t[0], t[1], t[2]});
  return inputs.emplace(years, std::move(in)).first->second;
}

void BM_MeshSkeleton(benchmark::State& state) {
  const Input& in = mesh_for(static_cast<int>(state.range(0)));
  fspm::stages::MeshSkeleton s;
  for (auto _ : state) {
    s = fspm::stages::mesh_skeleton(fspm::stages::weld_branch_mesh(in.vertices, in.faces));
    benchmark::DoNotOptimize(s.tree.size());
  }
  state.counters["vertices"] = static_cast<double>(in.vertices.size());
  state.counters["internodes"] = static_cast<double>(s.tree.size());
  state.counters["iterations"] = s.iterations;
}
BENCHMARK(BM_MeshSkeleton)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

// The contraction alone, on the welded mesh.
void BM_Contraction(benchmark::State& state) {
  const Input& in = mesh_for(static_cast<int>(state.range(0)));
  const fspm::stages::BranchMesh mesh = fspm::stages::weld_branch_mesh(in.vertices, in.faces);
  for (auto _ : state) {
    benchmark::DoNotOptimize(fspm::stages::contract_mesh(mesh).iterations);
  }
  state.counters["welded_vertices"] = static_cast<double>(mesh.vertices.size());
}
BENCHMARK(BM_Contraction)->Arg(8)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace
