#pragma once
// Main branching structure and leaf clusters (Pirk sec. 3.3.2). An edge (the segment of skeleton
// node u) has low confidence when the mean distance of its points from the line of the segment
// is above the reduced diameter d'(u) = f_s d(u) of eq. 3.2: its points are probably not one
// branch. Tracing from the root, the nodes reached before a low-confidence edge form the main
// skeleton; the points of all nodes beyond the low-confidence edges that start at one main node
// p_i form its cluster C_i. The root node always belongs to the main skeleton.
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

// Needs the radii of eq. 3.1 set on skeleton.tree; f_s > 0.
ClusterSplit split_clusters(const PointSet& points, const PointSkeleton& skeleton, double f_s);

}  // namespace fspm::scans
