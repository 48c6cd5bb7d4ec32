#pragma once
// Stray returns: points far from every other point of a scan (a bird, dust, a multipath or
// mixed-pixel return metres off the tree). Kept, such a point is joined to the tree by the
// neighbour graph's k nearest neighbours, however far, draws a skeleton branch through the air
// and widens the crown. A point is isolated when the mean distance to its k nearest neighbours
// exceeds `factor` times the median of that mean over the scan, and at least min_distance_m: the
// statistical outlier removal of Rusu et al. (2008), with a median for the mean and a factor far
// above the scan's own spread, so that the sparse points of a crown or of an airborne scan stay.
#include <cstddef>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct IsolatedPointsOptions {
  int neighbours = 8;
  double factor = 10.0;
  double min_distance_m = 1.0;
};

struct IsolatedPoints {
  PointSet kept;
  std::size_t removed = 0;
  double threshold_m = 0.0;  // the mean neighbour distance above which a point was removed
};

// The points without the isolated ones. Sets of fewer than neighbours + 2 points are kept whole.
IsolatedPoints remove_isolated_points(const PointSet& points,
                                      const IsolatedPointsOptions& options = {});

}  // namespace fspm::scans
