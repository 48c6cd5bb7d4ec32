// Branches recovered from simulated scans of grown trees with ground and leaves (docs/scans.md,
// "Validation"): the truth is the tree the scan was simulated from.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "fspm/tree_file.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/skeleton_comparison.hpp"

namespace fspm::scans {
namespace {

// A grown tree scanned from four positions (3 mm range noise, self-occlusion),
// with a ground of 20 000 points over 8 x 8 m sloping 5 % (2 cm noise) and 30 points within
// 5 cm of the end of each of its leaves (leaves are not in the simulator's occlusion).
PointSet realistic_scan(const TreeGraph& truth, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  PointSet scan = simulate_scan(truth, ScanOptions{}, rng);
  std::uniform_real_distribution<double> u(-4.0, 4.0), ball(-0.05, 0.05);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int i = 0; i < 20000; ++i) {
    const double x = u(rng), y = u(rng);
    scan.points.emplace_back(x, y, 0.05 * x + noise(rng) - 0.02);
  }
  for (NodeId n = 0; n < truth.size(); ++n) {
    if (truth.kind(n) != OrganKind::kLeaf) continue;
    for (int i = 0; i < 30; ++i) {
      scan.points.push_back(truth.end(n) + Eigen::Vector3d(ball(rng), ball(rng), ball(rng)));
    }
  }
  return scan;
}

// Branches at least 5 cm thick of grown trees of the three types, each scanned three times
// (seeds 1-3): in the branch skeleton (short side tips removed) and in the default main
// skeleton (the rest in clusters) at least 90 % are found with their fork within 20 cm and
// followed to half their length (scans/skeleton_comparison.hpp). Pirk's split alone finds few.
struct Recovered {
  std::size_t branches = 0, in_branch_skeleton = 0, in_main = 0, in_pirk = 0;
};

Recovered recover_branches(const std::string& tree_file) {
  const TreeGraph truth = read_tree_file(std::string(FSPM_SOURCE_DIR) + "/" + tree_file);
  Recovered out;
  EncodeOptions pirk;
  pirk.follow_main_axes = false;
  for (std::uint64_t seed : {1, 2, 3}) {
    const PointSet scan = realistic_scan(truth, seed);
    const EncodeResult r = encode_point_set(scan);
    EXPECT_GT(r.ground_points, 1000u) << tree_file << " " << seed;
    const BranchRecovery b = branch_recovery(truth, r.branch_skeleton, 0.05, 0.2);
    out.branches += b.branches, out.in_branch_skeleton += b.recovered;
    out.in_main += branch_recovery(truth, r.model.skeleton, 0.05, 0.2).recovered;
    out.in_pirk +=
        branch_recovery(truth, encode_point_set(scan, pirk).model.skeleton, 0.05, 0.2).recovered;
    EXPECT_LT(r.branch_skeleton.size(), r.full_skeleton.size()) << tree_file << " " << seed;
    EXPECT_LT(r.model.skeleton.size(), r.full_skeleton.size()) << tree_file << " " << seed;
    EXPECT_GT(r.model.clusters.size(), 10u) << tree_file << " " << seed;
  }
  return out;
}

TEST(SkeletonRecovery, BranchesOfGrownTreesScannedWithGroundAndLeaves) {
  Recovered all;
  for (const char* file : {"examples/trees/open_a12.treeb", "examples/trees/open_b12.treeb",
                           "examples/trees/open_c12.treeb"}) {
    const Recovered r = recover_branches(file);
    EXPECT_GE(r.branches, 3u * 3u) << file;  // at least three such branches per tree
    all.branches += r.branches, all.in_branch_skeleton += r.in_branch_skeleton;
    all.in_main += r.in_main, all.in_pirk += r.in_pirk;
  }
  EXPECT_EQ(all.branches, 3u * (5u + 5u + 3u));
  EXPECT_GE(all.in_branch_skeleton * 10, all.branches * 9)
      << all.in_branch_skeleton << " of " << all.branches;
  EXPECT_GE(all.in_main * 10, all.branches * 9) << all.in_main << " of " << all.branches;
  EXPECT_LT(all.in_pirk * 2, all.branches) << all.in_pirk << " of " << all.branches;
}

// Hand-built skeletons: a trunk with one thick branch; recovered with the fork moved 15 cm, not
// with it moved 30 cm, nor when the recovered branch stops short of half its length.
TEST(SkeletonRecovery, MetricNeedsTheForkAndTheBranch) {
  TreeGraph truth;
  NodeData d;
  d.radius = 0.1;
  d.start = {0, 0, 0}, d.end = {0, 0, 2};
  const NodeId trunk = truth.add_node(kNoNode, d);
  d.start = {0, 0, 2}, d.end = {0, 0, 4};
  truth.add_node(trunk, d);
  d.radius = 0.04, d.order = 1;
  d.start = {0, 0, 2}, d.end = {2, 0, 3};
  truth.add_node(trunk, d);
  const auto recovered = [](double fork_shift, double reach) {
    TreeGraph r;
    NodeData e;
    e.start = {0, 0, 0}, e.end = {0, 0, 2 + fork_shift};
    const NodeId t = r.add_node(kNoNode, e);
    e.start = e.end, e.end = {0, 0, 4};
    r.add_node(t, e);
    e.start = {0, 0, 2 + fork_shift}, e.end = {2 * reach, 0, 2 + reach};
    r.add_node(t, e);
    return r;
  };
  EXPECT_EQ(branch_recovery(truth, recovered(0.15, 1.0), 0.05, 0.2).recovered, 1u);
  EXPECT_EQ(branch_recovery(truth, recovered(0.3, 1.0), 0.05, 0.2).recovered, 0u);
  EXPECT_EQ(branch_recovery(truth, recovered(0.0, 0.3), 0.05, 0.2).recovered, 0u);
  EXPECT_EQ(branch_recovery(truth, recovered(0.0, 1.0), 0.1, 0.2).branches, 0u);  // too thin
}

}  // namespace
}  // namespace fspm::scans
