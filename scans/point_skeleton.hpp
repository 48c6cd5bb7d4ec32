#pragma once
// The skeletal graph of a point set (Pirk sec. 3.3.1): the shortest-path tree of the points is
// coarsened into a few dozen to a few hundred skeleton nodes by binning the points by their path
// length from the root (bins of bin_length_m) and joining, within one bin, the points the
// neighbour graph connects (as in Xu et al. 2007 and Livny et al. 2010). A skeleton node is the
// centroid of its points; its parent is the node holding the predecessor of its point nearest
// the root, always one bin lower, so the result is a tree. The segment of node u runs from its
// parent's centroid (the lowest point for the root) to its own.
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/neighbour_graph.hpp"
#include "scans/shortest_path_tree.hpp"

namespace fspm::scans {

struct PointSkeleton {
  TreeGraph tree;  // radius 0 until set_allometric_radii
  std::vector<std::uint32_t> node_of_point;
  // Points of node u: members[first[u] .. first[u + 1]).
  std::vector<std::uint32_t> first;
  std::vector<std::uint32_t> members;
};

// Throws ValueError for bin_length_m <= 0.
PointSkeleton build_point_skeleton(const PointSet& points, const NeighbourGraph& graph,
                                   const ShortestPathTree& paths, double bin_length_m);

// The default bin length: 1/40 of the extent of the path lengths (the distance from the root to
// the farthest point along the tree), at least 1 mm.
double default_bin_length_m(const ShortestPathTree& paths);

}  // namespace fspm::scans
