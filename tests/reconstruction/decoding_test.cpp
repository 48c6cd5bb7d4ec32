// The decoded tree and its instanced mesh (Pirk sec. 3.4, 3.5.2): node counts and attachments of
// the tree graph, one stored mesh per patch, and stochastic-pruning prefixes worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fspm/error.hpp"
#include "reconstruction/decoding.hpp"
#include "tests/reconstruction/hand_built.hpp"

namespace fspm::reconstruction {
namespace {

using testing::hand_library;
using testing::two_cluster_model;

Decoding hand_decoding(std::uint64_t seed) {
  Decoding d;
  d.library = hand_library();
  std::mt19937_64 rng(seed);
  d.placements = texture_clusters(two_cluster_model(), d.library, {}, rng);
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

}  // namespace
}  // namespace fspm::reconstruction
