#pragma once
// Ground points and the trunk's base in a scan of one tree. Terrestrial and airborne clouds of
// single trees usually keep some ground around the stem; the lowest point is then a ground point
// metres from the tree, and a shortest-path tree rooted there runs along the ground first. The
// ground is the lower envelope of the cloud: the lowest point of each square cell of the xy plane,
// a plane fitted by least squares to the cell minima near it (refitted three times, so cells whose
// lowest point is a branch drop out). Points less than `band_m` above that plane are ground when
// the band covers at least `min_ground_cells` cells, far more than a trunk's cross-section; a
// cloud cut off at the stem base keeps all its points. The root is then the lowest point of the
// densest column of the cloud's bottom slab (the trunk, not a shrub or stray point beside it).
#include <cstdint>
#include <vector>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct GroundOptions {
  double cell_m = 0.5;
  double band_m = 0.15;
  std::size_t min_ground_cells = 25;
};

// Indices of the points above the ground band (all of them when no ground is found).
std::vector<std::uint32_t> above_ground(const PointSet& points, const GroundOptions& options = {});

// The base of the trunk: the lowest point of the densest 0.25 m column (with its eight
// neighbouring columns) among the points within the lowest metre, or the lowest 15 % of the
// height when that is less. Throws ValueError for an empty set.
std::uint32_t trunk_base_point(const PointSet& points);

}  // namespace fspm::scans
