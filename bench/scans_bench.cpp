// Encoding a scanned tree into the cluster-based representation (Pirk sec. 3.3): a simulated
// scan of about one million points of the synthetic test tree (scans/synthetic_tree.hpp, 8
// main branches with 4 twigs each, four scanner positions, 3 mm range noise). Goal: under 2 s
// on one core, neighbour graph, shortest-path tree, skeleton, clusters and hulls included.
#include <benchmark/benchmark.h>

#include <random>

#include "bench/synthetic_scan_tree.hpp"
#include "scans/clusters_file.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"

namespace {

const fspm::scans::PointSet& million_point_scan() {
  static const fspm::scans::PointSet scan = [] {
    const fspm::scans::SyntheticTreeOptions t = fspm::bench::synthetic_scan_tree();
    fspm::scans::ScanOptions s;
    s.density_per_m2 = 130000.0;
    std::mt19937_64 rng(1);
    return fspm::scans::simulate_scan(fspm::scans::synthetic_tree(t), s, rng);
  }();
  return scan;
}

void run(benchmark::State& state, double voxel_m) {
  const fspm::scans::PointSet& scan = million_point_scan();
  fspm::scans::EncodeOptions options;
  options.voxel_m = voxel_m;
  std::size_t bytes = 0, clusters = 0, nodes = 0, thinned = 0;
  for (auto _ : state) {
    const fspm::scans::EncodeResult r = fspm::scans::encode_point_set(scan, options);
    bytes = fspm::scans::clusters_bytes(r.model).size();
    clusters = r.model.clusters.size();
    nodes = r.model.skeleton.size();
    thinned = r.thinned_points;
  }
  state.counters["points"] = static_cast<double>(scan.points.size());
  state.counters["thinned"] = static_cast<double>(thinned);
  state.counters["nodes"] = static_cast<double>(nodes);
  state.counters["clusters"] = static_cast<double>(clusters);
  state.counters["bytes"] = static_cast<double>(bytes);
}

// Default voxel thinning (1/1000 of the tree's extent).
void BM_EncodeMillionPoints(benchmark::State& state) { run(state, 0.0); }
// Every point in the neighbour graph.
void BM_EncodeMillionPointsUnthinned(benchmark::State& state) { run(state, -1.0); }

}  // namespace

BENCHMARK(BM_EncodeMillionPoints)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_EncodeMillionPointsUnthinned)->Unit(benchmark::kMillisecond)->Iterations(1);
