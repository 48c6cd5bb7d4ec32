// Bending in plastic adaptation: thick branches are solid (Pirk 5.3.2, after Shinozaki's pipe
// model), thin ones bend by eq. 4.6, and no bend carries a branch into a solid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "environment/growth_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/attribute_names.hpp"

namespace fspm::environment {
namespace {

NodeId add_segment(TreeGraph& t, NodeId parent, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& to, double radius, std::uint16_t order) {
  NodeData d;
  d.start = from;
  d.end = to;
  d.radius = radius;
  d.order = order;
  return t.add_node(parent, d);
}

// A vertical trunk of six 0.5 m internodes (radius 5 cm) with a skeleton branch (radius 2 cm, two
// 0.4 m internodes) at each node, turning a quarter further round each time, and a skeleton
// leader on top: seven skeleton tips. Every skeleton tip carries a fan of fine twigs (radius
// 2 mm) that the analysis turns into a leaf cluster. The trunk's internodes carry 7, 6, 5, 4, 3
// and 2 skeleton tips: the first three are solid. The laterals carry one or two: bendable.
struct Sapling {
  TreeGraph tree;
  std::vector<NodeId> trunk;       // trunk internodes, base first
  std::vector<NodeId> branch_tip;  // the last skeleton internode of every lateral
};

void add_twigs(TreeGraph& t, NodeId at, std::uint16_t order) {
  const Eigen::Vector3d base = t.end(at);
  const Eigen::Vector3d dir = t.direction(at);
  for (int k = 0; k < 4; ++k) {
    const double a = k * std::numbers::pi / 2.0;
    const Eigen::Vector3d side(std::cos(a), std::sin(a), 0.0);
    const Eigen::Vector3d end = base + 0.15 * (dir + 0.8 * side + Eigen::Vector3d::UnitZ() * 0.3);
    const NodeId twig = add_segment(t, at, base, end, 0.002, order + 1);
    add_segment(t, twig, end, end + 0.15 * (dir + 0.5 * side).normalized(), 0.002, order + 1);
  }
}

Sapling sapling() {
  Sapling s;
  TreeGraph& t = s.tree;
  NodeId prev = kNoNode;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  for (int k = 0; k < 6; ++k) {
    const Eigen::Vector3d next = at + Eigen::Vector3d(0, 0, 0.5);
    prev = add_segment(t, prev, at, next, 0.05, 0);
    s.trunk.push_back(prev);
    at = next;
  }
  // The laterals, in id order after the trunk.
  for (int k = 0; k < 6; ++k) {
    const NodeId node = s.trunk[static_cast<std::size_t>(k)];
    const double a = k * std::numbers::pi / 2.0 + 0.3;
    const Eigen::Vector3d dir = Eigen::Vector3d(std::cos(a), std::sin(a), 0.5).normalized();
    const Eigen::Vector3d p0 = t.end(node);
    const NodeId b1 = add_segment(t, node, p0, p0 + 0.4 * dir, 0.02, 1);
    const NodeId b2 = add_segment(t, b1, t.end(b1), t.end(b1) + 0.4 * dir, 0.02, 1);
    add_twigs(t, b2, 1);
    s.branch_tip.push_back(b2);
  }
  const NodeId top = s.trunk.back();
  const NodeId leader =
      add_segment(t, top, t.end(top), t.end(top) + Eigen::Vector3d(0, 0, 0.4), 0.02, 0);
  add_twigs(t, leader, 0);
  return s;
}

TEST(PlasticBending, ASolidTrunkStaysWhileItsThinBranchesBendAway) {
  const Sapling s = sapling();
  AnalysisParams params;
  params.skeleton_radius_m = 0.01;  // trunk and laterals are skeleton, the twigs clusters
  params.min_cluster_radius_m = 0.1;
  params.light_model = ClusterLightModel::kSky;
  // Type B's tropisms (Pirk 4.5.4), whose light and gravity nearly cancel on an upright shoot.
  params.phototropism = 0.45;
  params.gravitropism = 0.44;
  const TreeAnalysis a = analyze_tree(s.tree, params);
  ASSERT_TRUE(a.skeleton[s.trunk.front()]);
  ASSERT_TRUE(a.skeleton[s.branch_tip.front()]);
  ASSERT_GE(a.clusters.size(), 7u);
  // A wall 0.6 m east of the trunk, taller than the sapling (not touching any branch).
  Scene scene;
  scene.boxes.push_back(Box::wall({0.9, -20}, {0.9, 20}, 0.0, 10.0, 0.2));
  const AdaptationResult r = adapt_tree(s.tree, a, scene);
  const auto disp = r.tree.attribute("displacement");
  // The trunk's lower three internodes each carry at least five skeleton tips: they do not move
  // at all (nor does anything turn below them).
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(disp[s.trunk[k]], 0.0) << "trunk internode " << k;
  }
  // Some thin branch (one or two skeleton tips) bends, and the laterals' tips move away from the
  // wall on average.
  double moved = 0.0, shift_x = 0.0;
  for (const NodeId b : s.branch_tip) {
    moved = std::max(moved, disp[b]);
    shift_x += r.tree.end(b).x() - s.tree.end(b).x();
  }
  EXPECT_GT(moved, 0.02);
  EXPECT_LT(shift_x, 0.0);
}

TEST(PlasticBending, NoBendCarriesABranchIntoTheGroundOrTheWall) {
  // Type B at 20 years beside the 10 m wall 2 m east, with pruning by light off (c_psi = 0): a
  // branch can then only be pruned for standing in a solid. Every pruned branch must have stood
  // in the wall or the ground as grown; none may have been bent into one (before bends into
  // solids were refused, two thin branches of this tree swung below the ground).
  GrowthParams p = growth_preset("B");
  p.years = 20;
  p.seed = 1000;
  Scene open;
  open.ground = Ground{};
  const GrowthResult grown = grow_tree(p, open);
  Scene wall = open;
  wall.boxes.push_back(Box::wall({2.0, -20}, {2.0, 20}, 0.0, 10.0, 0.2));
  AnalysisParams ap;
  ap.phototropism = p.phototropism;
  ap.gravitropism = p.gravitropism;
  ap.pruning_strength = 0.0;
  const TreeAnalysis a = analyze_tree(grown.tree, ap);
  const AdaptationResult r = adapt_tree(grown.tree, a, wall);
  const auto pruned = r.tree.attribute(kPrunedAttribute);
  std::size_t bent_into = 0, grown_into = 0, surviving_in = 0;
  for (NodeId i = 1; i < r.tree.size(); ++i) {
    if (!a.skeleton[i]) continue;
    if (pruned[i] == 0.0) {
      surviving_in += wall.segment_blocked(r.tree.start(i), r.tree.end(i));
      continue;
    }
    if (pruned[r.tree.parent(i)] != 0.0) continue;  // inside a pruned subtree
    const bool as_grown = wall.segment_blocked(grown.tree.start(i), grown.tree.end(i));
    (as_grown ? grown_into : bent_into) += 1;
  }
  EXPECT_GT(r.bent_segments, 10u);  // the crown does bend
  EXPECT_GT(grown_into, 0u);        // the open crown reaches into the wall
  EXPECT_EQ(bent_into, 0u);
  EXPECT_EQ(surviving_in, 0u);
}

// Height of the highest internode end.
double height_m(const TreeGraph& t) {
  double h = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kInternode) h = std::max(h, t.end(i).z());
  }
  return h;
}

std::size_t internodes(const TreeGraph& t) {
  std::size_t n = 0;
  for (NodeId i = 0; i < t.size(); ++i) n += t.kind(i) == OrganKind::kInternode;
  return n;
}

TEST(PlasticBending, AdaptedTypeBKeepsTheHeightGrowthBesideTheWallKeeps) {
  // The growth model is the oracle (Pirk's set G): a 30-year type-B tree grown beside a 10 m wall
  // 2 m east keeps nearly the open tree's height and about three quarters of its internodes. The
  // same open tree adapted to the wall must keep its height too, and a comparable share of its
  // internodes (with every skeleton segment bending, this tree lost a third or more of its
  // height).
  GrowthParams p = growth_preset("B");
  p.years = 30;
  p.seed = 1017;
  Scene open;
  open.ground = Ground{};
  Scene wall = open;
  wall.boxes.push_back(Box::wall({2.0, -20}, {2.0, 20}, 0.0, 10.0, 0.2));
  const GrowthResult o = grow_tree(p, open);
  const GrowthResult g = grow_tree(p, wall);
  const double h_o = height_m(o.tree);
  const double kept_g =
      static_cast<double>(internodes(g.tree)) / static_cast<double>(internodes(o.tree));
  ASSERT_GT(height_m(g.tree), 0.85 * h_o);  // the oracle: growth keeps the height
  AnalysisParams ap;
  ap.phototropism = p.phototropism;
  ap.gravitropism = p.gravitropism;
  ap.min_cluster_radius_m = p.cluster_radius_m;
  const TreeAnalysis a = analyze_tree(o.tree, ap);
  const TreeGraph t = remove_pruned(adapt_tree(o.tree, a, wall).tree);
  const double kept_t =
      static_cast<double>(internodes(t)) / static_cast<double>(internodes(o.tree));
  std::printf(
      "type B, 30 years: height open %.2f, grown %.2f, adapted %.2f m; internodes kept "
      "grown %.2f, adapted %.2f\n",
      h_o, height_m(g.tree), height_m(t), kept_g, kept_t);
  EXPECT_GT(height_m(t), 0.85 * h_o);
  EXPECT_NEAR(kept_t, kept_g, 0.25);
}

}  // namespace
}  // namespace fspm::environment
