#pragma once
// Main branching structure and leaf clusters (Pirk sec. 3.3.2). An edge (the segment of skeleton
// node u) has low confidence when the mean distance of its points from the line of the segment
// is above the reduced diameter d'(u) = f_s d(u) of eq. 3.2: its points are probably not one
// branch. Tracing from the root, the nodes reached before a low-confidence edge form the main
// skeleton; the points of all nodes beyond the low-confidence edges that start at one main node
// p_i form its cluster C_i. The root node always belongs to the main skeleton.
//
// On real clouds eq. 3.2 alone stops at the trunk: with Table 3.1's gamma (1.2-1.9) eq. 3.1 gives
// a limb carrying a tenth of the skeleton's length a diameter of 1-6 % of the trunk's, far below
// the scatter of a crown bin's points (leaves, twigs, airborne sampling). With main axes followed
// (the default), a node also stays in the main skeleton when it continues its parent's axis
// (of the children with at least half the largest sibling's subtree, the straightest), when its
// subtree carries at least `main_branch_share` of the skeleton's length, or when it reaches at
// least `main_branch_reach` of the skeleton's longest path beyond its fork: the trunk runs to the
// top and every limb the scan resolves to its tip, and eq. 3.2 decides only for the short side
// tips, which become clusters. A share of the whole length falls with the number of limbs, and
// where limbs touch the shortest paths reach one through a short side chain of its neighbour;
// the reach does not depend on either.
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/point_skeleton.hpp"

namespace fspm::scans {

struct PointCluster {
  NodeId seed_node = kNoNode;  // p_i: the main-skeleton node (id in main_skeleton)
  std::vector<std::uint32_t> points;
  double branch_length_m = 0.0;  // summed segment lengths of its skeleton nodes
};

struct ClusterSplit {
  TreeGraph main_skeleton;      // the ancestor-closed confident part, ids renumbered
  std::vector<NodeId> main_of;  // node of the full skeleton -> main id, kNoNode if clustered
  std::vector<PointCluster> clusters;
};

// Mean distance of node u's points from the line through its segment (from its end point when
// the segment has zero length).
double mean_point_distance_m(const PointSet& points, const PointSkeleton& skeleton, NodeId u);

struct SplitOptions {
  double f_s = 0.98;                // eq. 3.2
  bool follow_main_axes = true;     // false: eq. 3.2 alone (Pirk)
  double main_branch_share = 0.05;  // of l(root), eq. 3.1's subtree length
  // A side branch reaching this share of the skeleton's longest path from the root (its longest
  // path from its fork to a tip) is a main limb too, however many limbs share the crown; 0: off.
  double main_branch_reach = 0.1;
  // Side tips shorter than this (scans/tip_pruning.hpp: split rings, leaf tufts, noise) are left
  // out of the lengths the main axes are chosen by; 0 counts every node.
  double spur_length_m = 0.0;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// Needs the radii of eq. 3.1 set on skeleton.tree; f_s > 0.
ClusterSplit split_clusters(const PointSet& points, const PointSkeleton& skeleton,
                            const SplitOptions& options);

}  // namespace fspm::scans
