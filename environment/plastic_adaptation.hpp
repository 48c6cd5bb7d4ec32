#pragma once
// Plastic adaptation (Pirk 4.4): a tree analysed in the open (tree_analysis.hpp) is bent and pruned
// for a new scene, age level by age level, oldest first. Per level: every skeleton segment of that
// age is bent by the rotation that takes its eq. 4.6 heading under the analysis-time tropism to its
// heading under the new light direction (so an unchanged environment leaves it unchanged), the
// rotation is applied to its subtree, the leaf clusters follow the mean offset of their nodes
// (Pirk 4.4.2), the light is recomputed and every lateral branch up to that age whose resources
// per length (eq. 4.11) fall below its minimum pruning factor (eq. 4.12) is pruned with its
// subtree. Pruned clusters lose translucency by eq. 4.14 or vanish.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "environment/scene.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

struct AdaptationResult {
  // The input tree with its moved nodes and the attributes "displacement" (distance the node's
  // end moved, m) and "pruned" (1 for a pruned node, which keeps its adapted position).
  TreeGraph tree;
  std::size_t pruned_nodes = 0;
  std::size_t bent_segments = 0;  // skeleton segments rotated by more than 1e-9 rad
  std::size_t tips = 0;           // internode tips that survived (no internode child)
  double mean_tip_displacement_m = 0.0;
  Eigen::Vector3d mean_tip_shift = Eigen::Vector3d::Zero();
  std::vector<LeafCluster> clusters;  // the adapted clusters (pruned ones removed)
};

// `analysis` must come from analyze_tree(tree). The scene's occluders shade the tree together with
// its own clusters; its sky gives the brightest point (global light). Throws ValueError when the
// analysis does not match the tree.
AdaptationResult adapt_tree(const TreeGraph& tree, const TreeAnalysis& analysis,
                            const Scene& scene);

// Tree-tree interaction, simplified: each tree is adapted with the other trees' analysed leaf
// clusters (at their input positions, non-solid) added to the scene, so facing sides shade each
// other. Unlike Pirk 4.4.3 the neighbours are not adapted in lock-step (their clusters do not
// move or vanish during the run). Trees are given in world coordinates. Throws ValueError when
// the sizes differ.
std::vector<AdaptationResult> adapt_trees(const std::vector<const TreeGraph*>& trees,
                                          const std::vector<const TreeAnalysis*>& analyses,
                                          const Scene& scene);

// Removes the nodes flagged "pruned"; returns the compacted tree.
TreeGraph remove_pruned(const TreeGraph& adapted);

}  // namespace fspm::environment
