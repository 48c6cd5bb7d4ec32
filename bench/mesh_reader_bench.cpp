// Reading branch meshes through the one mesh entry point (scans/mesh_file.hpp): the bark mesh of
// preset A grown for the given years (Arg), as fspm's tree mesher builds it, written once as
// binary PLY (read from memory: the bulk path for the writer's layout) and as binary glTF (read
// from its file by assimp). Goal: reading a 100 000-vertex mesh a small part of the one second
// `fspm stages MESH` aims at (docs/BENCHMARKS.md, developmental stages).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "environment/growth_model.hpp"
#include "fspm/input_file.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/tree_mesher.hpp"
#include "scans/mesh_file.hpp"
#include "scans/ply_reader.hpp"

namespace {

struct Files {
  std::string ply_bytes;
  std::string glb_path;
};

// The .glb files go when the program ends.
struct FileMap : std::map<int, Files> {
  ~FileMap() {
    for (const auto& [years, f] : *this) std::filesystem::remove(f.glb_path);
  }
};

const Files& files_for(int years) {
  static FileMap files;
  auto it = files.find(years);
  if (it != files.end()) return it->second;
  fspm::environment::GrowthParams p = fspm::environment::growth_preset("A");
  p.years = years;
  const fspm::graphics::TriangleMesh m =
      fspm::graphics::mesh_tree(fspm::environment::grow_tree(p).tree);
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  const std::string stem =
      "fspm_mesh_reader_bench_" + std::to_string(::getpid()) + "_" + std::to_string(years);
  const std::string ply = (dir / (stem + ".ply")).string();
  Files f;
  f.glb_path = (dir / (stem + ".glb")).string();
  fspm::graphics::write_ply(m, ply);
  fspm::graphics::write_glb(m, f.glb_path);
  f.ply_bytes = fspm::read_input_file(ply);
  std::filesystem::remove(ply);
  return files.emplace(years, std::move(f)).first->second;
}

void BM_ReadBinaryPlyMesh(benchmark::State& state) {
  const Files& f = files_for(static_cast<int>(state.range(0)));
  fspm::scans::GroupedMesh m;
  for (auto _ : state) {
    m = fspm::scans::parse_ply_mesh(f.ply_bytes, "bench.ply");
    benchmark::DoNotOptimize(m.faces.data());
  }
  state.counters["vertices"] = static_cast<double>(m.vertices.size());
  state.counters["faces"] = static_cast<double>(m.faces.size());
}
BENCHMARK(BM_ReadBinaryPlyMesh)->Arg(27)->Unit(benchmark::kMillisecond);

void BM_ReadGlbMesh(benchmark::State& state) {
  const Files& f = files_for(static_cast<int>(state.range(0)));
  fspm::scans::GroupedMesh m;
  for (auto _ : state) {
    m = fspm::scans::read_mesh_file(f.glb_path);
    benchmark::DoNotOptimize(m.faces.data());
  }
  state.counters["vertices"] = static_cast<double>(m.vertices.size());
  state.counters["faces"] = static_cast<double>(m.faces.size());
}
BENCHMARK(BM_ReadGlbMesh)->Arg(27)->Unit(benchmark::kMillisecond);

}  // namespace
