// The encoder on simulated scans of trees with a known skeleton (docs/scans.md, "Validation").
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include "scans/clusters_file.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/segment_distance.hpp"
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

// Pirk's split: eq. 3.2 alone decides where the main skeleton stops (EncodeOptions::
// follow_main_axes false, fspm encode --pirk-split).
EncodeOptions pirk_split() {
  EncodeOptions o;
  o.follow_main_axes = false;
  return o;
}

// The known answer: the synthetic tree's skeleton, trunk diameter 0.3 m, and its main skeleton
// (radius above 4 mm: trunk and the four main branches up to their last twig), which Pirk's split
// is to recover.
TEST(ScanValidation, RecoversTheMainSkeletonOfASyntheticTree) {
  const Case c = scanned_tree(1);
  const EncodeResult r = encode_point_set(c.scan, pirk_split());
  EXPECT_NEAR(r.model.root_diameter_m, 0.3, 0.3 * 0.07);
  const TreeGraph truth = main_skeleton(c.truth, 0.004);
  const SkeletonComparison cmp = compare_skeletons(truth, r.model.skeleton);
  EXPECT_GE(cmp.recovered_branches, 3u);                                 // at least one fork
  EXPECT_LT(cmp.edit_distance, static_cast<double>(cmp.true_branches));  // better than none
  EXPECT_LT(cmp.branch_point_error_m, 0.5);
  EXPECT_LT(cmp.position_error_m, 0.06);
  EXPECT_LT(cmp.diameter_error, 0.5);
  std::printf(
      "seed 1: %zu main nodes, %zu clusters, edit %.0f of %zu, branch points %.3f m, "
      "positions %.3f m, diameters %.2f, %zu bytes, %zu bridges\n",
      r.model.skeleton.size(), r.model.clusters.size(), cmp.edit_distance, cmp.true_branches,
      cmp.branch_point_error_m, cmp.position_error_m, cmp.diameter_error,
      clusters_bytes(r.model).size(), r.bridges);
  // The skeleton and hulls fit in a few kB (Pirk Table 3.2: 3-39 kB).
  EXPECT_LT(clusters_bytes(r.model).size(), 40000u);
}

// Distance from a point to the nearest segment of a skeleton.
double distance_to(const TreeGraph& t, const Eigen::Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (NodeId n = 0; n < t.size(); ++n)
    best = std::min(best, segment_distance(p, p, t.start(n), t.end(n)));
  return best;
}

// The point `share` of the way along the axis (chain of one order) that starts at node u.
Eigen::Vector3d along_axis(const TreeGraph& t, NodeId u, double share) {
  std::vector<NodeId> axis{u};
  for (bool more = true; more;) {
    more = false;
    for (NodeId c : t.children(axis.back())) {
      if (t.order(c) == t.order(u)) axis.push_back(c), more = true;
    }
  }
  double total = 0.0;
  for (NodeId n : axis) total += t.length(n);
  double left = share * total;
  for (NodeId n : axis) {
    if (left <= t.length(n)) return t.start(n) + (t.end(n) - t.start(n)) * (left / t.length(n));
    left -= t.length(n);
  }
  return t.end(axis.back());
}

// The default main skeleton follows the trunk to the top and each main branch to its tip, eq. 3.2
// sending the twigs to clusters: its nodes lie on the tree's axes (within 3 cm on average), and
// for the trunk and each of the four main branches it passes within 20 cm of the points half-way
// and four fifths of the way along the true axis. Pirk's split (eq. 3.2 alone) stops short.
TEST(ScanValidation, DefaultMainSkeletonFollowsTheMainBranchesToTheirTips) {
  const TreeGraph truth = synthetic_tree();
  std::vector<NodeId> axes{0};  // the trunk and the main branches (order 1)
  for (NodeId n = 1; n < truth.size(); ++n) {
    if (truth.order(n) == 1 && truth.order(truth.parent(n)) == 0) axes.push_back(n);
  }
  ASSERT_EQ(axes.size(), 5u);
  for (std::uint64_t seed : {1, 2, 3}) {
    const Case c = scanned_tree(seed);
    const EncodeResult r = encode_point_set(c.scan);
    const EncodeResult pirk = encode_point_set(c.scan, pirk_split());
    EXPECT_LT(compare_skeletons(truth, r.model.skeleton).position_error_m, 0.03) << seed;
    std::size_t followed = 0, followed_by_pirk = 0;
    for (NodeId a : axes) {
      for (double share : {0.5, 0.8}) {
        const Eigen::Vector3d p = along_axis(truth, a, share);
        followed += distance_to(r.model.skeleton, p) < 0.2;
        followed_by_pirk += distance_to(pirk.model.skeleton, p) < 0.2;
      }
    }
    std::printf(
        "seed %llu: %zu main nodes, %zu clusters; %zu of 10 axis points (Pirk's split %zu)\n",
        static_cast<unsigned long long>(seed), r.model.skeleton.size(), r.model.clusters.size(),
        followed, followed_by_pirk);
    EXPECT_EQ(followed, 10u) << seed;
    EXPECT_LT(followed_by_pirk, 10u) << seed;
  }
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
    EncodeOptions o = pirk_split();
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
