#pragma once
// Thinning a point set to one point per occupied voxel (the centroid of its points), so that the
// neighbour graph and shortest-path tree of a dense scan (millions of points, a few mm apart)
// work on the resolution the skeleton needs. Voxels are cubes of voxel_m from the set's lowest
// corner.
#include <cstdint>
#include <vector>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct ThinnedPoints {
  PointSet points;                    // one centroid per occupied voxel
  std::vector<std::uint32_t> counts;  // input points in each voxel
};

// Throws ValueError for voxel_m <= 0 or more than 2^21 voxels along one axis.
ThinnedPoints thin_to_voxels(const PointSet& points, double voxel_m);

}  // namespace fspm::scans
