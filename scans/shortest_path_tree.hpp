#pragma once
// The shortest-path tree of the neighbour graph from the lowest point (Pirk sec. 3.3.1): Dijkstra
// over the weights |u - v|^beta (Boost.Graph). Besides each point's predecessor it keeps the
// Euclidean length of its path from the root, by which the points are later binned into the
// skeleton's nodes.
#include <cstdint>
#include <vector>

#include "scans/neighbour_graph.hpp"

namespace fspm::scans {

struct ShortestPathTree {
  std::uint32_t root = 0;
  std::vector<std::uint32_t> predecessor;  // predecessor[root] == root
  std::vector<double> path_length_m;       // Euclidean length of the path from the root
};

// Index of the point with the smallest z (the first of equals). Requires a non-empty set.
std::uint32_t lowest_point(const PointSet& points);

ShortestPathTree shortest_path_tree(const PointSet& points, const NeighbourGraph& graph,
                                    std::uint32_t root);

}  // namespace fspm::scans
