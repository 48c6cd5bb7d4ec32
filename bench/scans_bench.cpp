// Encoding a scanned tree into the cluster-based representation (Pirk sec. 3.3): a simulated
// scan of about one million points of the synthetic test tree (scans/synthetic_tree.hpp, 8
// main branches with 4 twigs each, four scanner positions, 3 mm range noise). Goal: under 2 s
// on one core, neighbour graph, shortest-path tree, skeleton, clusters and hulls included.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "bench/synthetic_scan_tree.hpp"
#include "scans/clusters_file.hpp"
#include "scans/encoder.hpp"
#include "scans/las_reader.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/scanned_tree.hpp"
#include "scans/tree_measurements.hpp"

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

// The scan as an uncompressed LAS 1.2 file of point format 0 (ASPRS LAS 1.4 R15, table 3),
// millimetre scale, at projected coordinates (offset 500 000, 5 800 000, 300 m).
const std::string& million_point_las() {
  static const std::string bytes = [] {
    const auto& points = million_point_scan().points;
    std::string s(227, '\0');
    const auto put = [&s](std::size_t at, auto v) { std::memcpy(s.data() + at, &v, sizeof v); };
    std::memcpy(s.data(), "LASF", 4);
    put(24, std::uint8_t{1});
    put(25, std::uint8_t{2});
    put(94, std::uint16_t{227});
    put(96, std::uint32_t{227});
    put(105, std::uint16_t{20});
    put(107, static_cast<std::uint32_t>(points.size()));
    const double offset[3] = {500000.0, 5800000.0, 300.0};
    for (int c = 0; c < 3; ++c) {
      put(131 + 8 * static_cast<std::size_t>(c), 0.001);
      put(155 + 8 * static_cast<std::size_t>(c), offset[c]);
    }
    std::string record(20, '\0');
    for (const Eigen::Vector3d& p : points) {
      for (int c = 0; c < 3; ++c) {
        const auto v = static_cast<std::int32_t>(std::lround(p[c] / 0.001));
        std::memcpy(record.data() + 4 * c, &v, 4);
      }
      s += record;
    }
    return s;
  }();
  return bytes;
}

void BM_ReadLasMillionPoints(benchmark::State& state) {
  const std::string& las = million_point_las();
  std::size_t points = 0;
  for (auto _ : state) {
    points = fspm::scans::parse_las_points(las, "bench.las").points.size();
  }
  state.counters["points"] = static_cast<double>(points);
  state.counters["bytes"] = static_cast<double>(las.size());
}

// From the LAS bytes to the skeleton and the measurements (dbh, height, cylinders, volume), as
// fspm encode makes them: stray points left out first.
void BM_LasToMeasurementsMillionPoints(benchmark::State& state) {
  const std::string& las = million_point_las();
  double dbh = 0.0, volume = 0.0, cylinders = 0.0;
  for (auto _ : state) {
    const fspm::scans::PointSet points = fspm::scans::parse_las_points(las, "bench.las");
    const fspm::scans::ScannedTree tree = fspm::scans::encode_and_measure(points);
    const fspm::scans::TreeMeasurements& m = tree.measurements;
    dbh = m.dbh_m.value_or(0.0);
    volume = m.woody_volume_m3;
    cylinders = static_cast<double>(m.cylinders.size());
  }
  state.counters["dbh_m"] = dbh;
  state.counters["volume_m3"] = volume;
  state.counters["cylinders"] = cylinders;
}

}  // namespace

BENCHMARK(BM_ReadLasMillionPoints)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_LasToMeasurementsMillionPoints)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK(BM_EncodeMillionPoints)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_EncodeMillionPointsUnthinned)->Unit(benchmark::kMillisecond)->Iterations(1);
