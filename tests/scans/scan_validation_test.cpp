// The encoder on simulated scans of trees with a known skeleton (docs/scans.md, "Validation").
#include <gtest/gtest.h>

#include <random>

#include "scans/clusters_file.hpp"
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

// The known answer: the synthetic tree's skeleton, trunk diameter 0.3 m, and its main skeleton
// (radius above 4 mm: trunk and the four main branches up to their last twig).
TEST(ScanValidation, RecoversTheMainSkeletonOfASyntheticTree) {
  const Case c = scanned_tree(1);
  const EncodeResult r = encode_point_set(c.scan);
  EXPECT_NEAR(r.model.root_diameter_m, 0.3, 0.3 * 0.07);
  const TreeGraph truth = main_skeleton(c.truth, 0.004);
  const SkeletonComparison cmp = compare_skeletons(truth, r.model.skeleton);
  EXPECT_GE(cmp.recovered_branches, 3u);                                 // at least one fork
  EXPECT_LT(cmp.edit_distance, static_cast<double>(cmp.true_branches));  // better than none
  EXPECT_LT(cmp.branch_point_error_m, 0.5);
  EXPECT_LT(cmp.position_error_m, 0.06);
  EXPECT_LT(cmp.diameter_error, 0.5);
  // The skeleton and hulls fit in a few kB (Pirk Table 3.2: 3-39 kB).
  EXPECT_LT(clusters_bytes(r.model).size(), 40000u);
}

// The skeleton nodes split between the main skeleton and the clusters: their lengths add up to
// the full skeleton's.
TEST(ScanValidation, ClusterBranchLengthsAreTheSkeletonSegmentsTheyTook) {
  const Case c = scanned_tree(3);
  const EncodeResult r = encode_point_set(c.scan);
  ASSERT_GT(r.model.clusters.size(), 0u);
  const auto length = [](const TreeGraph& t) {
    double sum = 0.0;
    for (NodeId n = 0; n < t.size(); ++n) sum += t.length(n);
    return sum;
  };
  double clustered = 0.0;
  for (const ClusterHull& h : r.model.clusters) {
    EXPECT_GT(h.branch_length_m, 0.0);
    clustered += h.branch_length_m;
  }
  EXPECT_NEAR(length(r.model.skeleton) + clustered, length(r.full_skeleton), 1e-9);
}

// Pirk eq. 3.2 and Fig. 3.11: a smaller f_s marks more edges as low-confidence, so more points
// go to clusters; at f_s = 0.5 the trunk's own points (mean distance r = d/2) fail the test and
// nearly the whole tree is one cluster.
TEST(ScanValidation, LargerFsLeavesFewerPointsInClusters) {
  const Case c = scanned_tree(2);
  std::size_t previous = c.scan.points.size() + 1;
  for (double fs : {0.5, 0.8, 0.9, 1.0, 1.5, 2.0}) {
    EncodeOptions o;
    o.species.f_s = fs;
    const EncodeResult r = encode_point_set(c.scan, o);
    std::size_t clustered = 0;
    for (const ClusterHull& h : r.model.clusters) clustered += h.point_count;
    EXPECT_LE(clustered, previous) << "f_s " << fs;
    previous = clustered;
    if (fs == 0.5) {
      EXPECT_EQ(r.model.clusters.size(), 1u);
      EXPECT_GT(clustered, c.scan.points.size() * 9 / 10);
    }
  }
}

}  // namespace
}  // namespace fspm::scans
