// Cluster texturing (Pirk sec. 3.4): eq. 3.3 by hand, the selection and fitting on hand-built
// clusters whose patch counts follow from eq. 3.3, docking points checked against a solid-angle
// point-in-hull oracle, and seeded reproducibility.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fspm/error.hpp"
#include "scan_decoding/cluster_texturing.hpp"
#include "scan_decoding/hull_geometry.hpp"
#include "tests/scan_decoding/hand_built.hpp"

namespace fspm::scan_decoding {
namespace {

using testing::hand_library;
using testing::hand_options;
using testing::inside_by_solid_angle;
using testing::two_cluster_model;

TEST(PatchFit, IsEquation33) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_DOUBLE_EQ(patch_fit(1.0, 1.0, z, z), 1.0);
  EXPECT_DOUBLE_EQ(patch_fit(1.0, 2.0, z, z), 2.0);  // max/min, either way round
  EXPECT_DOUBLE_EQ(patch_fit(2.0, 1.0, z, z), 2.0);
  const Eigen::Vector3d tilted = Eigen::Vector3d(1, 0, 1).normalized();
  EXPECT_NEAR(patch_fit(0.5, 0.5, z, tilted), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(patch_fit(0.5, 1.5, z, tilted), 3.0 * std::sqrt(0.5), 1e-15);
}

TEST(PatchSelection, SimilarThenBestFitting) {
  const SpeciesLibrary lib = hand_library();
  const TextureOptions options;
  Docking seed;  // thickness 1, straight up
  // Patch 1 (0.5: ratio 2) is similar; 2 (ratio 3) and 3 (pointing down) are not.
  EXPECT_EQ(similar_patches(lib, seed, options), (std::vector<std::uint32_t>{0, 1}));
  // |d - 1|: patch 0 exactly 0, patch 1 |2 - 1| = 1.
  EXPECT_EQ(best_fitting_patches(lib, {0, 1}, seed, options), (std::vector<std::uint32_t>{0}));
  Docking lateral;
  lateral.thickness = 0.5;
  lateral.direction = Eigen::Vector3d(1, 0, 1).normalized();
  // Patch 0: 2 cos 45 = 1.414, patch 1: cos 45 = 0.707, so patch 1 (|d-1| = 0.29 < 0.41 - 0.1).
  EXPECT_EQ(best_fitting_patches(lib, similar_patches(lib, lateral, options), lateral, options),
            (std::vector<std::uint32_t>{1}));
}

TEST(HullGeometry, CrossingsOfABox) {
  const scans::ClusterHull box = testing::box_hull({-1, -1, 2.5}, {1, 1, 4.5}, 0);
  const std::vector<double> ts =
      ray_hull_crossings(box, Eigen::Vector3d(0.1, 0.2, 2.0), Eigen::Vector3d::UnitZ());
  ASSERT_EQ(ts.size(), 2u);
  EXPECT_NEAR(ts[0], 0.5, 1e-12);
  EXPECT_NEAR(ts[1], 2.5, 1e-12);
  EXPECT_TRUE(inside_hull(box, {0.3, -0.2, 3.0}));
  EXPECT_FALSE(inside_hull(box, {0.3, -0.2, 4.6}));
  EXPECT_FALSE(inside_hull(box, {1.2, 0.0, 3.0}));
}

// Each textured cluster: patch 0 at the seed (the only |d - 1| = 0), scaled to reach the top of
// the box (2.5 / 1), its two docking points at (seed + 2 up), inside, each taking patch 1 (see
// SimilarThenBestFitting) scaled by 0.5 / cos 45 = 0.707 to the top; patch 1 has no docking
// points. 3 patches per box, none in the cluster without triangles.
TEST(ClusterTexturing, CountsFollowFromEquation33) {
  const scans::ClusterModel model = two_cluster_model();
  std::mt19937_64 rng(5);
  const std::vector<PlacedPatch> placed =
      texture_clusters(model, hand_library(), hand_options(), rng);
  ASSERT_EQ(placed.size(), 6u);
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const PlacedPatch& p = placed[k];
    EXPECT_EQ(p.cluster, k / 3);
    if (k % 3 == 0) {
      EXPECT_EQ(p.patch, 0u);
      EXPECT_EQ(p.parent, kNoPlacement);
      EXPECT_NEAR(p.scale, 2.5, 1e-9);
      EXPECT_NEAR(p.fit, 1.0, 1e-12);
    } else {
      EXPECT_EQ(p.patch, 1u);
      EXPECT_EQ(p.parent, k - k % 3);
      EXPECT_EQ(p.docking, k % 3 - 1);
      EXPECT_NEAR(p.scale, std::sqrt(0.5), 1e-9);
      EXPECT_NEAR(p.fit, std::sqrt(0.5), 1e-9);
      EXPECT_EQ(p.depth, 1);
    }
  }
}

TEST(ClusterTexturing, DockingPointsLieOnTheSkeletonOrInsideTheHull) {
  const scans::ClusterModel model = two_cluster_model();
  std::mt19937_64 rng(11);
  const std::vector<PlacedPatch> placed =
      texture_clusters(model, hand_library(), hand_options(), rng);
  ASSERT_FALSE(placed.empty());
  for (const PlacedPatch& p : placed) {
    const scans::ClusterHull& hull = model.clusters[p.cluster];
    if (p.parent == kNoPlacement) {
      EXPECT_LT((p.translation - model.skeleton.end(hull.seed_node)).norm(), 1e-12);
    } else {
      EXPECT_LT(p.parent, static_cast<std::size_t>(&p - placed.data()));  // parents first
      EXPECT_TRUE(inside_by_solid_angle(hull, p.translation)) << p.translation.transpose();
    }
    // The patch axis reaches at most the hull's far side: its tip is inside or on it.
    const Eigen::Vector3d tip = p.to_world(hand_library().patches[p.patch].direction);
    const Eigen::Vector3d inward = 1e-6 * (p.translation - tip);
    EXPECT_TRUE(inside_by_solid_angle(hull, tip + inward)) << tip.transpose();
  }
}

TEST(ClusterTexturing, DockingPointsTooNearTheHullStayEmpty) {
  TextureOptions options = hand_options();
  options.min_scale_ratio = 0.3;  // 0.707 < 0.3 * 2.5: the lateral patches are refused
  std::mt19937_64 rng(5);
  const std::vector<PlacedPatch> placed =
      texture_clusters(two_cluster_model(), hand_library(), options, rng);
  EXPECT_EQ(placed.size(), 2u);
  options = hand_options();
  options.max_depth = 0;  // only the seeds' patches
  EXPECT_EQ(texture_clusters(two_cluster_model(), hand_library(), options, rng).size(), 2u);
}

// Pirk 3.4: of patches that fit eq. 3.3 equally well, the one that suits the cluster's geometry.
// A copy of patch 0 without docking points ties with it at the seed (same thickness and
// direction); the seed always takes patch 0, whose docking points lie inside the box, so the
// cluster is filled further (3 patches), never the copy that would end it (1 patch).
TEST(ClusterTexturing, EqualFitsGoToThePatchThatKeepsFillingTheHull) {
  SpeciesLibrary lib = hand_library();
  Patch end_here = lib.patches[0];
  end_here.dockings.clear();
  lib.patches.push_back(end_here);
  const auto copy = static_cast<std::uint32_t>(lib.patches.size() - 1);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<PlacedPatch> placed =
        texture_cluster(two_cluster_model(), 0, lib, hand_options(), rng);
    ASSERT_EQ(placed.size(), 3u) << seed;
    EXPECT_EQ(placed[0].patch, 0u) << seed;
    EXPECT_NE(placed[0].patch, copy);
  }
}

// Past Pirk's texturing (3 patches, 2.5 + 2 x 0.707 m, see CountsFollowFromEquation33), further
// branchlets start at the seed point until the cluster's branch length is reached; a patch is
// placed only while it brings the length nearer to it, so the length ends within half the longest
// patch the box admits from the seed point (its far corner, |(1, 1, 2.5)| = 2.87 m) of it. Without
// a branch length, or with match_branch_length off, the result is Pirk's.
TEST(ClusterTexturing, FurtherBranchletsUpToTheClustersBranchLength) {
  scans::ClusterModel model = two_cluster_model();
  model.clusters[0].branch_length_m = 10.0;
  const SpeciesLibrary lib = hand_library();
  const auto length_of = [&](const std::vector<PlacedPatch>& placed) {
    double sum = 0.0;
    for (const PlacedPatch& p : placed) sum += p.scale * lib.patches[p.patch].internode_length_m;
    return sum;
  };
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    std::mt19937_64 rng(seed);
    const std::vector<PlacedPatch> placed = texture_cluster(model, 0, lib, hand_options(), rng);
    const double length = length_of(placed);
    EXPECT_NEAR(length, 10.0, 0.5 * std::sqrt(1.0 + 1.0 + 2.5 * 2.5)) << seed;
    std::size_t seeds = 0;
    for (const PlacedPatch& p : placed) {
      if (p.parent != kNoPlacement) continue;
      ++seeds;
      EXPECT_LT((p.translation - model.skeleton.end(1)).norm(), 1e-12);
      const Eigen::Vector3d tip = p.to_world(lib.patches[p.patch].direction);
      EXPECT_TRUE(
          testing::inside_by_solid_angle(model.clusters[0], tip + 1e-6 * (p.translation - tip)))
          << tip.transpose();
    }
    EXPECT_GT(seeds, 1u) << seed;
  }
  TextureOptions pirk_only = hand_options();
  pirk_only.match_branch_length = false;
  std::mt19937_64 rng(1);
  EXPECT_EQ(texture_cluster(model, 0, lib, pirk_only, rng).size(), 3u);
  model.clusters[0].branch_length_m = 0.0;
  EXPECT_EQ(texture_cluster(model, 0, lib, hand_options(), rng).size(), 3u);
}

TEST(ClusterTexturing, SameSeedSameResult) {
  const SpeciesLibrary lib = make_species_library("default", {3, 5, 1});
  const scans::ClusterModel model = two_cluster_model();
  std::mt19937_64 a(42), b(42), c(43);
  const std::vector<PlacedPatch> pa = texture_clusters(model, lib, {}, a);
  const std::vector<PlacedPatch> pb = texture_clusters(model, lib, {}, b);
  const std::vector<PlacedPatch> pc = texture_clusters(model, lib, {}, c);
  ASSERT_EQ(pa.size(), pb.size());
  ASSERT_GT(pa.size(), 2u);
  bool differs = pa.size() != pc.size();
  for (std::size_t k = 0; k < pa.size(); ++k) {
    EXPECT_EQ(pa[k].patch, pb[k].patch);
    EXPECT_EQ(pa[k].translation, pb[k].translation);
    EXPECT_EQ(pa[k].rotation, pb[k].rotation);
    if (k < pc.size()) differs = differs || pa[k].rotation != pc[k].rotation;
  }
  EXPECT_TRUE(differs);  // the roll about the docking direction is drawn from the seed
}

TEST(ClusterTexturing, RefusesWhatItCannotTexture) {
  scans::ClusterModel model = two_cluster_model();
  std::mt19937_64 rng(1);
  EXPECT_THROW(texture_clusters(model, SpeciesLibrary{}, {}, rng), ValueError);
  model.clusters[0].seed_node = 7;
  EXPECT_THROW(texture_clusters(model, hand_library(), hand_options(), rng), ValueError);
  TextureOptions bad;
  bad.max_thickness_ratio = 0.5;
  EXPECT_THROW(texture_clusters(two_cluster_model(), hand_library(), bad, rng), ValueError);
}

}  // namespace
}  // namespace fspm::scan_decoding
