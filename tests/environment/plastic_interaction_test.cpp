// Plastic trees beyond the single-tree basics: lock-step tree-tree schedules, leaf density from
// light (eq. 4.13), clusters against solid obstacles, re-adaptation from one analysis, and the
// per-cluster light against the independent LightModel.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "environment/cluster_light.hpp"
#include "environment/growth_model.hpp"
#include "environment/leaf_light.hpp"
#include "environment/light_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/solid_push.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::environment {
namespace {

const GrowthResult& grown(int years) {
  static std::map<int, GrowthResult> cache;
  auto it = cache.find(years);
  if (it == cache.end()) {
    // The sky model branches at most nodes, so the analysis (Pirk 4.3.1) tells the ages apart.
    GrowthParams p = growth_preset("A", BudLightModel::kSky);
    p.years = years;
    it = cache.emplace(years, grow_tree(p)).first;
  }
  return it->second;
}

TreeGraph translated(const TreeGraph& tree, const Eigen::Vector3d& offset) {
  TreeGraph t = tree;
  for (NodeId i = 0; i < t.size(); ++i) {
    const double len = t.length(i);
    const Eigen::Vector3d dir = t.direction(i);
    t.set_segment(i, t.start(i) + offset, t.end(i) + offset);
    t.set_length(i, len);
    t.set_direction(i, dir);
  }
  return t;
}

void expect_same(const AdaptationResult& a, const AdaptationResult& b) {
  ASSERT_EQ(a.tree.size(), b.tree.size());
  EXPECT_EQ(a.pruned_nodes, b.pruned_nodes);
  EXPECT_EQ(a.bent_segments, b.bent_segments);
  double worst = 0.0;
  for (NodeId i = 0; i < a.tree.size(); ++i) {
    worst = std::max(worst, (a.tree.end(i) - b.tree.end(i)).norm());
  }
  // Multi-tree runs visit neighbours in another order (a wider grid): rounding only.
  EXPECT_LT(worst, 1e-6);
}

// Physics does not depend on where the tree and its wall stand: moved together by an offset, the
// adapted tree is the same tree moved by that offset.
TEST(PlasticLockStep, ATreeAndItsWallMovedTogetherAdaptTheSame) {
  const GrowthResult& g = grown(10);
  const Eigen::Vector3d offset(12.0, -7.0, 0.0);
  const TreeGraph moved = translated(g.tree, offset);
  const TreeAnalysis a = analyze_tree(g.tree);
  const TreeAnalysis a_moved = analyze_tree(moved);
  Scene here, there;
  here.boxes.push_back(Box::wall({1.5, -20}, {1.5, 20}, 0.0, 30.0, 0.2));
  there.boxes.push_back(Box::wall({1.5 + offset.x(), -20 + offset.y()},
                                  {1.5 + offset.x(), 20 + offset.y()}, 0.0, 30.0, 0.2));
  const auto r = adapt_trees({&g.tree}, {&a}, here);
  const auto r_moved = adapt_trees({&moved}, {&a_moved}, there);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_EQ(r_moved.size(), 1u);
  ASSERT_GT(r[0].bent_segments, 0u);
  EXPECT_EQ(r[0].pruned_nodes, r_moved[0].pruned_nodes);
  ASSERT_EQ(r[0].tree.size(), r_moved[0].tree.size());
  double worst = 0.0;
  for (NodeId i = 0; i < r[0].tree.size(); ++i) {
    worst = std::max(worst, (r_moved[0].tree.end(i) - offset - r[0].tree.end(i)).norm());
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(PlasticLockStep, FarApartTreesOfDifferentAgesAdaptAsAlone) {
  // A 12-year and a younger 8-year tree far beyond each other's shadow volumes, each beside its
  // own wall: the aligned schedule (the younger starts later) must not change either result.
  const GrowthResult& old_tree = grown(12);
  const GrowthResult& young = grown(8);
  const TreeGraph far = translated(young.tree, {200.0, 0, 0});
  const TreeAnalysis a_old = analyze_tree(old_tree.tree);
  const TreeAnalysis a_young = analyze_tree(far);
  ASSERT_GT(a_old.max_age, a_young.max_age);
  Scene scene;
  scene.boxes.push_back(Box::wall({1.5, -20}, {1.5, 20}, 0.0, 30.0, 0.2));
  scene.boxes.push_back(Box::wall({201.5, -20}, {201.5, 20}, 0.0, 30.0, 0.2));
  const auto together = adapt_trees({&old_tree.tree, &far}, {&a_old, &a_young}, scene);
  expect_same(together[0], adapt_tree(old_tree.tree, a_old, scene));
  expect_same(together[1], adapt_tree(far, a_young, scene));
}

TEST(PlasticLockStep, YoungNeighbourStillShadesTheOldTree) {
  // A young tree beside an old one: lock-step with aligned schedules, the old tree prunes on the
  // side facing the young one and leans away from it.
  const TreeGraph old_tree = translated(grown(12).tree, {-1.0, 0, 0});
  const TreeGraph young = translated(grown(9).tree, {1.0, 0, 0});
  const TreeAnalysis a_old = analyze_tree(old_tree);
  const TreeAnalysis a_young = analyze_tree(young);
  const auto r = adapt_trees({&old_tree, &young}, {&a_old, &a_young}, Scene{});
  std::printf("old beside young: old pruned %zu shift x %.3f; young pruned %zu shift x %.3f\n",
              r[0].pruned_nodes, r[0].mean_tip_shift.x(), r[1].pruned_nodes,
              r[1].mean_tip_shift.x());
  EXPECT_LT(r[0].mean_tip_shift.x(), 0.0);
  EXPECT_GT(r[1].mean_tip_shift.x(), 0.0);
}

TEST(PlasticAdaptation, UnchangedSceneNeedsNoLightEvaluation) {
  // Pirk 4.6, "applied only in the affected areas": nothing changed, nothing is recomputed.
  const GrowthResult& g = grown(12);
  const TreeAnalysis a = analyze_tree(g.tree);
  const AdaptationResult r = adapt_tree(g.tree, a, Scene{});
  EXPECT_EQ(r.light_evaluations, 0u);
  // With Pirk's eq. 4.3 cluster light (`sky`, evaluated cluster by cluster where the change
  // reaches), a small obstacle far below the crown's side touches only a few clusters; the
  // default canopy light evaluates the whole crown again whenever something moved.
  AnalysisParams sky;
  sky.light_model = ClusterLightModel::kSky;
  const TreeAnalysis a_sky = analyze_tree(g.tree, sky);
  EXPECT_EQ(adapt_tree(g.tree, a_sky, Scene{}).light_evaluations, 0u);
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({6.0, -0.5, 0.0}, {7.0, 0.5, 1.0}));
  const AdaptationResult s = adapt_tree(g.tree, a_sky, scene);
  EXPECT_LT(s.light_evaluations, a.clusters.size());
}

TEST(PlasticAdaptation, ReadaptsFromTheAnalysedStateWithoutReanalysing) {
  const GrowthResult& g = grown(12);
  const TreeAnalysis a = analyze_tree(g.tree);
  Scene wall;
  wall.boxes.push_back(Box::wall({1.5, -20}, {1.5, 20}, 0.0, 30.0, 0.2));
  Scene west;
  west.boxes.push_back(Box::wall({-1.5, -20}, {-1.5, 20}, 0.0, 30.0, 0.2));
  const AdaptationResult first = adapt_tree(g.tree, a, wall);
  const AdaptationResult moved = adapt_tree(g.tree, a, west);
  const AdaptationResult back = adapt_tree(g.tree, a, wall);
  expect_same(first, back);  // no state carried over between scenes
  EXPECT_LT(first.mean_tip_shift.x(), 0.0);
  EXPECT_GT(moved.mean_tip_shift.x(), 0.0);
}

TEST(PlasticAdaptation, LeafDensityFollowsTheLight) {
  // Pirk eq. 4.13 with rho(i) = i: open scene -> density 1; beside a wall (pruning off, so the
  // shaded clusters stay) the foliage thins out (Fig. 4.7). Reported per side: the far side is
  // shaded too, by the crown that leaned over it.
  const GrowthResult& g = grown(12);
  const TreeAnalysis open_analysis = analyze_tree(g.tree);
  const AdaptationResult open = adapt_tree(g.tree, open_analysis, Scene{});
  for (const LeafCluster& c : open.clusters) EXPECT_DOUBLE_EQ(c.density, 1.0);
  AnalysisParams params;
  params.pruning_strength = 0.0;
  const TreeAnalysis a = analyze_tree(g.tree, params);
  Scene scene;
  scene.boxes.push_back(Box::wall({1.5, -20}, {1.5, 20}, 0.0, 30.0, 0.2));
  const AdaptationResult r = adapt_tree(g.tree, a, scene);
  ASSERT_EQ(r.clusters.size(), a.clusters.size());
  double near_sum = 0.0, far_sum = 0.0, near_n = 0.0, far_n = 0.0;
  for (std::size_t k = 0; k < r.clusters.size(); ++k) {
    const LeafCluster& c = r.clusters[k];
    EXPECT_GE(c.density, 0.0);
    EXPECT_LE(c.density, 2.0);
    if (a.clusters[k].center.x() > 0.0) {
      near_sum += c.density, near_n += 1;
    } else {
      far_sum += c.density, far_n += 1;
    }
  }
  std::printf("mean leaf density beside the wall: wall side %.3f, far side %.3f\n",
              near_sum / near_n, far_sum / far_n);
  EXPECT_LT((near_sum + far_sum) / (near_n + far_n), 0.8);
  ASSERT_TRUE(r.tree.has_attribute("leaf_density"));
  const auto dens = r.tree.attribute("leaf_density");
  for (const LeafCluster& c : r.clusters) {
    for (const NodeId m : c.nodes) EXPECT_DOUBLE_EQ(dens[m], c.density);
  }
}

// A leaf's "light" after adaptation: unchanged in an open scene; beside a wall nan where pruned,
// at most 1, and on average near the light an independent LightModel gives the adapted leaves
// (the estimate scales each leaf's recorded light by its cluster's change of light).
TEST(PlasticAdaptation, LeavesCarryTheirLightAfterAdaptation) {
  const GrowthResult& g = grown(12);
  const auto before = g.tree.attribute("light");
  const AdaptationResult open = adapt_tree(g.tree, analyze_tree(g.tree), Scene{});
  const auto same = open.tree.attribute("light");
  for (NodeId i = 0; i < g.tree.size(); ++i) {
    if (g.tree.kind(i) != OrganKind::kLeaf) continue;
    EXPECT_EQ(same[i], before[i]) << i;
  }
  Scene scene;
  scene.boxes.push_back(Box::wall({1.0, -20}, {1.0, 20}, 0.0, 30.0, 0.2));
  const AdaptationResult r = adapt_tree(g.tree, analyze_tree(g.tree), scene);
  const auto light = r.tree.attribute("light");
  const auto pruned = r.tree.attribute("pruned");
  TreeGraph exact = r.tree;
  record_leaf_light(exact, scene);
  const auto oracle = exact.attribute("light");
  double sum = 0.0, oracle_sum = 0.0, before_sum = 0.0;
  std::size_t n = 0;
  for (NodeId i = 0; i < r.tree.size(); ++i) {
    if (r.tree.kind(i) != OrganKind::kLeaf) continue;
    if (pruned[i] != 0.0) {
      EXPECT_TRUE(std::isnan(light[i])) << i;
      continue;
    }
    ASSERT_FALSE(std::isnan(light[i])) << i;
    EXPECT_GE(light[i], 0.0);
    EXPECT_LE(light[i], 1.0);
    sum += light[i], oracle_sum += oracle[i], before_sum += before[i], ++n;
  }
  ASSERT_GT(n, 10u);
  std::printf("mean leaf light: grown %.3f, adapted %.3f, LightModel on the adapted %.3f\n",
              before_sum / n, sum / n, oracle_sum / n);
  EXPECT_LT(sum, before_sum);  // the wall takes light
  EXPECT_NEAR(sum / n, oracle_sum / n, 0.25 * oracle_sum / n);
}

TEST(PlasticAdaptation, TreeCloseToAWallBendsAndPrunes) {
  // The python test's case (python/tests/test_environment.py): the shipped 12-year tree of type
  // A (examples/trees/open_a12.treeb), a 6 m wall at x = 0.7.
  struct {
    TreeGraph tree;
  } g{read_tree_file(FSPM_SOURCE_DIR "/examples/trees/open_a12.treeb")};
  // Pirk's eq. 4.3 cluster light (`sky`); the default canopy light bends the crown as far
  // (0.83 m against 0.91 m) but prunes nothing here (docs/environment.md).
  AnalysisParams params;
  params.light_model = ClusterLightModel::kSky;
  const TreeAnalysis a = analyze_tree(g.tree, params);
  Scene scene;
  scene.boxes.push_back(Box::wall({0.7, -20}, {0.7, 20}, 0.0, 6.0, 0.2));
  const AdaptationResult r = adapt_tree(g.tree, a, scene);
  std::printf("12 years close to a wall: pruned %zu, shift x %.3f\n", r.pruned_nodes,
              r.mean_tip_shift.x());
  EXPECT_LT(r.mean_tip_shift.x(), 0.0);
  EXPECT_GT(r.pruned_nodes, 0u);
}

TEST(PlasticSolids, SignedDistanceMatchesClosedForms) {
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({0, 0, 0}, {2, 2, 2}));
  scene.spheres.push_back({{10, 0, 0}, 1.0, 0.0, true});
  scene.spheres.push_back({{-10, 0, 0}, 1.0, 0.0, false});  // not solid: ignored
  Eigen::Vector3d n;
  EXPECT_NEAR(signed_distance_to_solids(scene, {3, 1, 1}, &n), 1.0, 1e-12);
  EXPECT_NEAR((n - Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance_to_solids(scene, {3, 3, 1}, &n), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(signed_distance_to_solids(scene, {1, 1, 1.5}, &n), -0.5, 1e-12);
  EXPECT_NEAR((n - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(signed_distance_to_solids(scene, {10, 0, 3}, &n), 2.0, 1e-12);
  EXPECT_GT(signed_distance_to_solids(scene, {-10, 0, 0}, &n), 5.0);
}

TEST(PlasticSolids, ClustersInASolidObstacleAreClippedOrPushedOut) {
  const GrowthResult& g = grown(12);
  const TreeAnalysis a = analyze_tree(g.tree);
  // A solid block through the east half of the crown (translucent, so it barely shades).
  Scene scene;
  Box block = Box::from_min_max({0.8, -10, 1.5}, {10, 10, 30});
  block.translucency = 0.95;
  scene.boxes.push_back(block);
  const AdaptationResult r = adapt_tree(g.tree, a, scene);
  std::printf("clusters %zu, clipped or pushed %zu\n", r.clusters.size(), r.pushed_clusters);
  EXPECT_GT(r.pushed_clusters, 0u);
  for (const LeafCluster& c : r.clusters) {
    EXPECT_GE(signed_distance_to_solids(scene, c.center, nullptr), c.radius_m - 1e-6);
    EXPECT_NEAR(c.translucency, std::pow(0.5, c.radius_m), 1e-9);  // eq. 4.4 after clipping
    for (const NodeId m : c.nodes) EXPECT_FALSE(scene.inside_solid(r.tree.end(m))) << m;
  }
}

TEST(ClusterLight, MatchesTheLightModelAtClusterCentres) {
  // The per-cluster field against the independent LightModel (same sky, same shadow volumes):
  // equal up to the single-precision direction tests (the `sky` cluster light).
  const GrowthResult& g = grown(12);
  AnalysisParams params;
  params.light_model = ClusterLightModel::kSky;
  const TreeAnalysis a = analyze_tree(g.tree, params);
  Scene scene;
  scene.sky.directions = a.params.light_directions;
  scene.sky.significance = a.params.light_significance;
  scene.spheres = cluster_spheres(a.clusters);
  const LightModel model(scene);
  double worst = 0.0, worst_dir = 0.0;
  for (std::uint32_t c = 0; c < a.clusters.size(); ++c) {
    const LightSample s = model.evaluate(a.clusters[c].center, c);
    worst = std::max(worst, std::abs(s.light - a.cluster_light[c]));
    worst_dir = std::max(worst_dir, (s.direction - a.cluster_direction[c]).norm());
  }
  std::printf("cluster light vs LightModel: worst |di| %.2e, worst |d dir| %.2e\n", worst,
              worst_dir);
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(worst_dir, 1e-3);
}

TEST(ClusterLight, ObstacleVisibilityIsCachedUntilTheClusterMoves) {
  ClusterLightField field(64, 0.01, Eigen::Vector3d::UnitZ());
  const std::vector<Eigen::Vector3d> centers = {{0, 0, 1}};
  const std::vector<double> radii = {0.3}, gammas = {0.5};
  field.set_clusters(centers, radii, gammas);
  Scene scene;
  scene.boxes.push_back(Box::from_min_max({-50, -50, 5}, {50, 50, 6}));  // an opaque roof
  field.set_obstacles(scene);
  EXPECT_TRUE(field.update_obstacles(0));
  field.evaluate(0);
  EXPECT_LT(field.light(0), 0.05);
  EXPECT_FALSE(field.obstacles_stale(0));
  field.move(0, {0, 0, 7});  // above the roof
  EXPECT_TRUE(field.obstacles_stale(0));
  EXPECT_TRUE(field.update_obstacles(0));
  field.mark_moved();
  field.evaluate(0);
  EXPECT_DOUBLE_EQ(field.light(0), 1.0);
}

}  // namespace
}  // namespace fspm::environment
