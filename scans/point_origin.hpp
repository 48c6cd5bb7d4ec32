#pragma once
// Recentring point sets that come with projected (GIS) coordinates: x of 500 000 m and y of
// 5 800 000 m leave a float 0.5 m of resolution and make least-squares fits on squared
// coordinates meaningless. Computations run on points relative to an origin (the bounding box
// minimum rounded down to whole metres) and their results are moved back by it.
#include <Eigen/Core>

#include "fspm/tree_graph.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

// floor() of the bounding box minimum of the points, componentwise; zero for an empty set.
Eigen::Vector3d point_set_origin(const PointSet& points);

// The points minus `origin`.
PointSet relative_to(const PointSet& points, const Eigen::Vector3d& origin);

// Moves every segment of `tree` by `offset` (directions and lengths stay).
void translate_tree(TreeGraph& tree, const Eigen::Vector3d& offset);

}  // namespace fspm::scans
