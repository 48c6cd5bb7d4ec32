#pragma once
// Plastic adaptation (Pirk 4.4): a tree analysed in the open (tree_analysis.hpp) is bent and pruned
// for a new scene, age level by age level, oldest first. Per level: every skeleton segment of that
// age is bent by the rotation that takes its eq. 4.6 heading under the analysis-time tropism to its
// heading under the new light direction (so an unchanged environment leaves it unchanged), scaled
// by its bendability: none for a branch carrying five or more skeleton tips (Pirk 5.3.2, pipe
// model), and never into a solid; the rotation is carried to its subtree (one pass over the younger
// skeleton per level), the leaf clusters follow their anchor (Pirk 4.4.2), the light is updated and
// every lateral branch up to that age whose resources per length (eq. 4.11) fall below its minimum
// pruning factor (eq. 4.12) is pruned with its subtree. Pruned clusters lose translucency by
// eq. 4.14 or vanish; the leaf density follows the light (eq. 4.13); clusters that end up in a
// solid obstacle are pushed out.
//
// The clusters' light comes from the light model the analysis used (AnalysisParams::light_model, a
// PlasticLight of light_model_registry.hpp), told after every step which clusters moved and which
// were pruned. Only the affected parts are recomputed (Pirk 4.6): light is evaluated per leaf
// cluster, starting from the analysis' cache. The `canopy` and `shadow_grid` lights evaluate the
// whole crown again after a step that moved or pruned something; with the `sky` light a cluster
// is re-evaluated only when clusters in its shadow neighbourhood moved relative to it by more than
// kDriftTolerance_m (and 15 % of their distance) or vanished, enough to change its light by about
// 5 % (clusters carried by the same bent branch keep their relative positions), when it turned by
// more than kTurnTolerance_rad against the sky, or when its cached obstacle visibility changed.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "environment/scene.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

struct AdaptationResult {
  // The input tree with its moved nodes and the attributes "displacement" (distance the node's
  // end moved, m) and "pruned" (1 for a pruned node, which keeps its adapted position). A leaf's
  // "light", when the tree has it, is scaled by its cluster's change of light (eq. 4.13's ratio);
  // pruned leaves have none (nan).
  TreeGraph tree;
  std::size_t pruned_nodes = 0;
  std::size_t bent_segments = 0;  // skeleton segments rotated by more than 1e-4 rad
  std::size_t tips = 0;           // internode tips that survived (no internode child)
  double mean_tip_displacement_m = 0.0;
  Eigen::Vector3d mean_tip_shift = Eigen::Vector3d::Zero();
  // Where the pruning happened: the centroid of the pruned internodes' ends in the input tree
  // (zero when nothing was pruned), to set against the input tree's `internode_centroid`.
  Eigen::Vector3d pruned_centroid = Eigen::Vector3d::Zero();
  Eigen::Vector3d internode_centroid = Eigen::Vector3d::Zero();
  std::vector<LeafCluster> clusters;  // the adapted clusters (pruned ones removed)
  std::size_t light_evaluations = 0;  // cluster light evaluations the adaptation needed
  std::size_t pushed_clusters = 0;    // clusters moved out of solid obstacles
};

inline constexpr double kDriftTolerance_m = 0.1;
inline constexpr double kTurnTolerance_rad = 0.2;

// `analysis` must come from analyze_tree(tree). The scene's occluders shade the tree together with
// its own clusters; its sky gives the brightest point (global light). Throws ValueError when the
// analysis does not match the tree.
AdaptationResult adapt_tree(const TreeGraph& tree, const TreeAnalysis& analysis,
                            const Scene& scene);

// Tree-tree interaction (Pirk 4.4.3): the trees (in world coordinates) are adapted together, age
// level by age level in lock-step, sharing one light field, so every tree's clusters shade the
// others and move or vanish while the others adapt. A younger tree (fewer age levels) starts later
// so that all trees finish at the same step. Throws ValueError when the sizes differ or an
// analysis does not match its tree.
std::vector<AdaptationResult> adapt_trees(const std::vector<const TreeGraph*>& trees,
                                          const std::vector<const TreeAnalysis*>& analyses,
                                          const Scene& scene);

// Removes the nodes flagged "pruned"; returns the compacted tree.
TreeGraph remove_pruned(const TreeGraph& adapted);

}  // namespace fspm::environment
