// Decoding a cluster-based tree (Pirk sec. 3.4, Table 3.2): the synthetic test tree scanned and
// encoded once (as in scans_bench), its species library built once (a library serves every tree
// of its species), then per iteration the clusters textured (eq. 3.3) and the result built as an
// instanced mesh (skeleton tubes, each patch meshed once and placed by instances), or further
// flattened into one explicit mesh. Pirk Table 3.2 (GPU): 3-18 ms full, 1-4 ms with LOD.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstring>
#include <random>
#include <vector>

#include "bench/synthetic_scan_tree.hpp"
#include "fspm/huge_pages.hpp"
#include "scan_decoding/decoding.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"

namespace {

namespace rc = fspm::scan_decoding;

const fspm::scans::ClusterModel& model() {
  static const fspm::scans::ClusterModel m = [] {
    const fspm::scans::SyntheticTreeOptions t = fspm::bench::synthetic_scan_tree();
    fspm::scans::ScanOptions s;
    s.density_per_m2 = 20000.0;
    std::mt19937_64 rng(1);
    const fspm::scans::PointSet scan =
        fspm::scans::simulate_scan(fspm::scans::synthetic_tree(t), s, rng);
    fspm::scans::EncodeOptions e;
    e.species.f_s = 0.9;
    return fspm::scans::encode_point_set(scan, e).model;
  }();
  return m;
}

const rc::SpeciesLibrary& library() {
  static const rc::SpeciesLibrary lib = rc::make_species_library("default", {});
  return lib;
}

void run(benchmark::State& state, bool flatten, bool lod, bool match_branch_length = true) {
  const fspm::scans::ClusterModel& m = model();
  rc::Decoding d;
  d.library = library();
  rc::DecodeMeshOptions options;
  if (lod) options.camera_m = Eigen::Vector3d(0.0, -60.0, 5.0);
  rc::TextureOptions texture;
  texture.match_branch_length = match_branch_length;
  std::size_t triangles = 0, instances = 0;
  for (auto _ : state) {
    std::mt19937_64 rng(1);
    d.placements = rc::texture_clusters(m, d.library, texture, rng);
    const fspm::graphics::InstancedMesh mesh = rc::decoded_mesh(m, d, options);
    if (flatten) {
      const fspm::graphics::TriangleMesh flat = mesh.flatten();
      benchmark::DoNotOptimize(flat.positions.data());
    }
    triangles = mesh.triangle_count();
    instances = mesh.instances.size();
  }
  state.counters["clusters"] = static_cast<double>(m.clusters.size());
  state.counters["instances"] = static_cast<double>(instances);
  state.counters["triangles"] = static_cast<double>(triangles);
}

// Pirk's largest tree has 3 M triangles; ours decodes to a few thousand. The explicit mesh of a
// 3 M-triangle scene: the decoded instances repeated (side by side) until 3 M triangles, then
// flattened, which is what the explicit path adds per triangle.
void BM_FlattenThreeMillionTriangles(benchmark::State& state) {
  const fspm::scans::ClusterModel& m = model();
  rc::Decoding d;
  d.library = library();
  std::mt19937_64 rng(1);
  d.placements = rc::texture_clusters(m, d.library, {}, rng);
  fspm::graphics::InstancedMesh mesh = rc::decoded_mesh(m, d, {});
  const std::vector<fspm::graphics::MeshInstance> one = mesh.instances;
  for (int copy = 1; mesh.triangle_count() < 3000000; ++copy) {
    for (fspm::graphics::MeshInstance i : one) {
      i.translation.x() += 20.0f * static_cast<float>(copy);
      mesh.instances.push_back(i);
    }
  }
  // The floor in the same run: a fresh buffer of the explicit mesh's bytes, backed by huge pages
  // as flatten's columns are, written once with memset (page faults and zeroing included).
  double flatten_s = 0.0, memset_s = 0.0;
  std::size_t bytes = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    {
      const fspm::graphics::TriangleMesh flat = mesh.flatten();
      benchmark::DoNotOptimize(flat.positions.data());
      bytes = static_cast<std::size_t>(fspm::graphics::TriangleMesh::bytes_for(
          flat.vertex_count(), flat.triangle_count(), flat.attributes.size()));
    }
    const auto t1 = std::chrono::steady_clock::now();
    {
      std::vector<unsigned char> buffer;
      buffer.reserve(bytes);
      fspm::advise_huge_pages(buffer.data(), bytes);
      std::memset(buffer.data(), 1, bytes);
      benchmark::DoNotOptimize(buffer.data());
      benchmark::ClobberMemory();
    }
    const auto t2 = std::chrono::steady_clock::now();
    flatten_s += std::chrono::duration<double>(t1 - t0).count();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
    memset_s += std::chrono::duration<double>(t2 - t1).count();
  }
  state.counters["instances"] = static_cast<double>(mesh.instances.size());
  state.counters["triangles"] = static_cast<double>(mesh.triangle_count());
  state.counters["megabytes"] = static_cast<double>(bytes) / 1e6;
  state.counters["ratio_to_fresh_memset"] = flatten_s / memset_s;
}

void BM_DecodeInstanced(benchmark::State& state) { run(state, false, false); }
void BM_DecodeInstancedLod60m(benchmark::State& state) { run(state, false, true); }
void BM_DecodeExplicitMesh(benchmark::State& state) { run(state, true, false); }
// Pirk's texturing alone (fspm decode --docking-only), the peer of BM_DecodeInstanced.
void BM_DecodeInstancedDockingOnly(benchmark::State& state) { run(state, false, false, false); }

}  // namespace

BENCHMARK(BM_DecodeInstanced)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeInstancedLod60m)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeExplicitMesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DecodeInstancedDockingOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlattenThreeMillionTriangles)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->UseManualTime();
