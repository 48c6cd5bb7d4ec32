// The encoder on simulated scans of trees with a known skeleton (docs/scans.md, "Validation").
#include <gtest/gtest.h>

#include <random>

#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/skeleton_comparison.hpp"
#include "scans/synthetic_tree.hpp"

namespace fspm::scans {
namespace {

struct Case {
  TreeGraph truth;
  PointSet scan;
};

Case scanned_tree(std::uint64_t seed) {
  Case c;
  c.truth = synthetic_tree();
  std::mt19937_64 rng(seed);
  c.scan = simulate_scan(c.truth, ScanOptions{}, rng);
  return c;
}

TEST(ScanValidation, RecoversTheMainSkeletonOfASyntheticTree) {
  const Case c = scanned_tree(1);
  const EncodeResult r = encode_point_set(c.scan);
  const SkeletonComparison cmp = compare_skeletons(main_skeleton(c.truth, 0.004), r.model.skeleton);
  std::printf(
      "points %zu nodes %zu clusters %zu d_root %.4f ed %.1f (%zu vs %zu) bp %.3f pos %.3f diam "
      "%.3f\n",
      r.points, r.model.skeleton.size(), r.model.clusters.size(), r.model.root_diameter_m,
      cmp.edit_distance, cmp.true_branches, cmp.recovered_branches, cmp.branch_point_error_m,
      cmp.position_error_m, cmp.diameter_error);
}

TEST(ScanValidation, LargerFsGivesFewerClusteredPoints) {
  const Case c = scanned_tree(2);
  for (double fs : {0.5, 0.8, 0.9, 0.95, 0.98, 1.0, 1.2, 1.5}) {
    EncodeOptions o;
    o.species.f_s = fs;
    const EncodeResult r = encode_point_set(c.scan, o);
    std::size_t clustered = 0;
    for (const ClusterHull& h : r.model.clusters) clustered += h.point_count;
    std::printf("fs %.2f clusters %zu clustered %zu nodes %zu\n", fs, r.model.clusters.size(),
                clustered, r.model.skeleton.size());
  }
}

}  // namespace
}  // namespace fspm::scans
