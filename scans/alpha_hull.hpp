#pragma once
// The envelope of a cluster (Pirk sec. 3.3.2): a CGAL alpha shape of the cluster's points with
// alpha = alpha_factor * alpha_min, alpha_min being the smallest alpha for which the shape is
// one solid component (CGAL's find_optimal_alpha(1)); Pirk uses alpha = 5 alpha_min. CGAL's
// alpha is a squared ball radius, and the factor applies to it. Before the triangulation the
// points are thinned to one per cell of a grid of max_cells cells along the longest side of the
// cluster's box, which bounds the hull's size (the .clusters file) and the time on millions of
// points. Fewer than four cells, or cells all in one plane, give the cell points and no triangles.
#include <array>
#include <cstdint>
#include <vector>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct AlphaHull {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  double alpha = 0.0;                                   // the alpha used (squared radius)
};

struct AlphaHullOptions {
  double alpha_factor = 5.0;
  int max_cells = 12;
};

AlphaHull alpha_hull(const std::vector<Eigen::Vector3d>& points,
                     const AlphaHullOptions& options = {});

// The thinning step alone: the centroid of the points of each occupied grid cell.
std::vector<Eigen::Vector3d> thin_to_grid(const std::vector<Eigen::Vector3d>& points,
                                          int max_cells);

}  // namespace fspm::scans
