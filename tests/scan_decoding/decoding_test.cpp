// The decoded tree and its instanced mesh (Pirk sec. 3.4, 3.5.2): node counts and attachments of
// the tree graph, one stored mesh per patch, and stochastic-pruning prefixes worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <utility>

#include "fspm/error.hpp"
#include "scan_decoding/decoding.hpp"
#include "scans/encoder.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/synthetic_tree.hpp"
#include "tests/scan_decoding/hand_built.hpp"

namespace fspm::scan_decoding {
namespace {

using testing::hand_library;
using testing::two_cluster_model;

Decoding hand_decoding(std::uint64_t seed) {
  Decoding d;
  d.library = hand_library();
  std::mt19937_64 rng(seed);
  d.placements = texture_clusters(two_cluster_model(), d.library, testing::hand_options(), rng);
  return d;
}

TEST(DecodedTree, SkeletonThenPatchesHangingWhereTheyDock) {
  const scans::ClusterModel model = two_cluster_model();
  const Decoding d = hand_decoding(3);
  ASSERT_EQ(d.placements.size(), 6u);
  const TreeGraph tree = decoded_tree(model, d);
  // 3 skeleton nodes; per cluster patch 0 (1 internode + 4 leaves), twice patch 1 (1 + 2).
  EXPECT_EQ(tree.size(), 3u + 2 * (5 + 3 + 3));
  EXPECT_EQ(tree.end(1), model.skeleton.end(1));
  // Cluster 0's first patch: node 3, under skeleton node 1, from its end, 2.5 m long up.
  EXPECT_EQ(tree.parent(3), 1u);
  EXPECT_TRUE(tree.start(3).isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_TRUE(tree.end(3).isApprox(Eigen::Vector3d(0, 0, 4.5)));
  EXPECT_NEAR(tree.radius(3), 2.5 * 0.05, 1e-12);
  EXPECT_EQ(tree.order(3), 1);
  // Its laterals hang from its internode (node 3), at 0.8 of it, order 2.
  EXPECT_EQ(tree.parent(8), 3u);
  EXPECT_TRUE(tree.start(8).isApprox(Eigen::Vector3d(0, 0, 4)));
  EXPECT_EQ(tree.order(8), 2);
  EXPECT_NEAR(tree.length(8), std::sqrt(0.5), 1e-9);
  // Cluster 1 hangs at skeleton node 2 (order 1), so its first patch has order 2.
  EXPECT_EQ(tree.parent(14), 2u);
  EXPECT_EQ(tree.order(14), 2);
}

TEST(DecodedMesh, EachPatchStoredOnce) {
  const scans::ClusterModel model = two_cluster_model();
  const Decoding d = hand_decoding(3);
  DecodeMeshOptions options;
  const graphics::InstancedMesh mesh = decoded_mesh(model, d, options);
  ASSERT_EQ(mesh.instances.size(), 7u);  // the skeleton and six patches
  EXPECT_EQ(mesh.meshes.size(), 3u);     // the skeleton, patch 0, patch 1
  EXPECT_EQ(mesh.meshes[1].triangle_count(graphics::Material::kLeaf), 2u * 4);  // quads
  EXPECT_EQ(mesh.meshes[2].triangle_count(graphics::Material::kLeaf), 2u * 2);
  const std::size_t explicit_triangles = mesh.meshes[0].triangle_count() +
                                         2 * mesh.meshes[1].triangle_count() +
                                         4 * mesh.meshes[2].triangle_count();
  EXPECT_EQ(mesh.triangle_count(), explicit_triangles);
  EXPECT_EQ(mesh.flatten().triangle_count(), explicit_triangles);
  // The instance places the patch: its base at the seed point, scaled 2.5.
  EXPECT_TRUE(mesh.instances[1].translation.isApprox(Eigen::Vector3f(0, 0, 2)));
  EXPECT_NEAR(mesh.instances[1].linear.col(0).norm(), 2.5f, 1e-5f);
}

TEST(DecodedMesh, StochasticPruningPrefixesByDistance) {
  // (20 / d)^2 of the leaves, rounded up: 20 leaves at 40 m -> 5, at 60 m -> ceil(2.22) = 3,
  // nearer than 20 m all; never none.
  EXPECT_EQ(drawn_leaves(20, 40.0, 20.0), 5u);
  EXPECT_EQ(drawn_leaves(20, 60.0, 20.0), 3u);
  EXPECT_EQ(drawn_leaves(20, 10.0, 20.0), 20u);
  EXPECT_EQ(drawn_leaves(4, 1000.0, 20.0), 1u);
  const scans::ClusterModel model = two_cluster_model();
  const Decoding d = hand_decoding(3);
  DecodeMeshOptions options;
  options.camera_m = Eigen::Vector3d(0, -40, 2);  // 40 m from cluster 0's seed point
  options.prune_distance_m = 20.0;
  const graphics::InstancedMesh mesh = decoded_mesh(model, d, options);
  ASSERT_EQ(mesh.instances.size(), 7u);
  for (std::size_t k = 1; k < mesh.instances.size(); ++k) {
    const PlacedPatch& p = d.placements[k - 1];
    const double distance = (*options.camera_m - p.translation).norm();
    const std::size_t all = d.library.patches[p.patch].leaves;
    // By hand: the share (20 / distance)^2 of `all`, rounded up, at least one.
    const double share = std::min(1.0, std::pow(20.0 / distance, 2));
    const auto expected = static_cast<std::size_t>(std::max(1.0, std::ceil(share * all)));
    EXPECT_EQ(mesh.meshes[mesh.instances[k].mesh].triangle_count(graphics::Material::kLeaf),
              2 * expected)
        << k;
  }
  // Cluster 0's first patch (4 leaves at 40 m): ceil(4 / 4) = 1 leaf.
  EXPECT_EQ(mesh.meshes[mesh.instances[1].mesh].triangle_count(graphics::Material::kLeaf), 2u);
  options.prune_distance_m = 0.0;
  EXPECT_THROW(decoded_mesh(model, d, options), ValueError);
}

TEST(Decoding, SameSeedSameTree) {
  const scans::ClusterModel model = two_cluster_model();
  DecodeOptions options;
  options.library.branchlets = 3;
  options.seed = 9;
  const TreeGraph a = decoded_tree(model, decode_clusters(model, options));
  const TreeGraph b = decoded_tree(model, decode_clusters(model, options));
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), model.skeleton.size());
  for (NodeId n = 0; n < a.size(); ++n) {
    ASSERT_EQ(a.parent(n), b.parent(n));
    ASSERT_EQ(a.end(n), b.end(n));
  }
  options.species = "no-such-tree";
  EXPECT_THROW(decode_clusters(model, options), ValueError);
}

double internode_length_m(const TreeGraph& t) {
  double sum = 0.0;
  for (NodeId n = 0; n < t.size(); ++n) sum += t.kind(n) == OrganKind::kInternode ? t.length(n) : 0;
  return sum;
}

// A tree of known branch length (scans/synthetic_tree.hpp), scanned from four sides and encoded.
// Decoding textures each cluster up to the branch length its skeleton segments had, so the decoded
// tree is as long as the scan's skeleton (within 10 %: the last patch of a cluster may end half a
// patch from its length), and that comes within 30 % of the true tree (the skeleton of a scanned
// surface runs through the centroids of bins of points, not the branch axes).
TEST(Decoding, RestoresTheBranchLengthOfAScannedTree) {
  const TreeGraph truth = scans::synthetic_tree();
  const double true_m = internode_length_m(truth);
  for (std::uint64_t seed = 4; seed <= 6; ++seed) {
    std::mt19937_64 rng(seed);
    const scans::PointSet scan = scans::simulate_scan(truth, scans::ScanOptions{}, rng);
    const scans::ClusterModel model = scans::encode_point_set(scan).model;
    ASSERT_GT(model.clusters.size(), 0u);
    double scanned_m = internode_length_m(model.skeleton);
    for (const scans::ClusterHull& h : model.clusters) scanned_m += h.branch_length_m;
    DecodeOptions options;
    options.seed = seed;
    const Decoding decoding = decode_clusters(model, options);
    const double decoded_m = internode_length_m(decoded_tree(model, decoding));
    // The same seed gives the same patches, however often it is run.
    for (int again = 0; again < 3; ++again) {
      const Decoding other = decode_clusters(model, options);
      ASSERT_EQ(other.placements.size(), decoding.placements.size()) << seed;
      for (std::size_t k = 0; k < other.placements.size(); ++k) {
        ASSERT_EQ(other.placements[k].translation, decoding.placements[k].translation) << k;
      }
    }
    std::printf("true %.2f m, scanned %.2f m, decoded %.2f m\n", true_m, scanned_m, decoded_m);
    EXPECT_NEAR(decoded_m / scanned_m, 1.0, 0.1) << seed;
    EXPECT_NEAR(decoded_m / true_m, 1.0, 0.3) << seed;
  }
}

// A cluster hull far larger than a branchlet (a 6 m box, as airborne crowns give): the patches
// are not blown up to it. Every leaf and patch internode of the decoded tree is at most the
// species' leaf and internode length (species_sizes); without the bound they grow several times.
TEST(Decoding, LeavesAndInternodesKeepTheSpeciesSizes) {
  scans::ClusterModel model;
  NodeData d;
  d.end = {0, 0, 2};
  d.radius = 0.2;
  model.skeleton.add_node(kNoNode, d);
  model.clusters.push_back(testing::box_hull({-3, -3, 2.5}, {3, 3, 8.5}, 0));
  model.clusters.back().branch_length_m = 60.0;
  for (const char* species : {"default", "palm", "pine"}) {
    model.species = species;
    const SpeciesSizes sizes = species_sizes(species);
    const auto longest = [&](const TextureOptions& texture) {
      DecodeOptions options;
      options.texture = texture;
      const TreeGraph tree = decoded_tree(model, decode_clusters(model, options));
      double leaf = 0.0, internode = 0.0;
      for (NodeId n = model.skeleton.size(); n < tree.size(); ++n) {
        (tree.kind(n) == OrganKind::kLeaf ? leaf : internode) =
            std::max(tree.kind(n) == OrganKind::kLeaf ? leaf : internode, tree.length(n));
      }
      return std::pair{leaf, internode};
    };
    const auto [leaf, internode] = longest({});
    EXPECT_GT(leaf, 0.5 * sizes.leaf_length_m) << species;
    EXPECT_LE(leaf, sizes.leaf_length_m * (1.0 + 1e-9)) << species;
    EXPECT_LE(internode, sizes.internode_length_m * (1.0 + 1e-9)) << species;
    TextureOptions unbounded;
    unbounded.max_scale = std::numeric_limits<double>::infinity();
    const auto [big_leaf, big_internode] = longest(unbounded);
    EXPECT_GT(big_leaf, 2.0 * sizes.leaf_length_m) << species;
    EXPECT_GT(big_internode, 2.0 * sizes.internode_length_m) << species;
  }
}

}  // namespace
}  // namespace fspm::scan_decoding
