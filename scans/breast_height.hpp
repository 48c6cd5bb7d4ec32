#pragma once
// The stem as foresters measure it. At breast height, the trunk's points (those nearest to the
// skeleton's order-0 axis) in a horizontal slice 1.2-1.4 m above the lowest point, and a circle
// fitted to their horizontal positions (Kasa 1976, scans/circle_fit.hpp) for the DBH. The stem
// is compact when its points lie on a circle (rms below a fifth of the radius plus 5 mm) of
// diameter at most max_diameter_m: a wall, a hedge or a crown reaching down is not. The same fit
// on a slice at the foot (stem_low_m, stem_high_m) tells a tree forked below breast height (a
// compact stem there) from no tree at all. Near the
// base (0.3-0.6 m), the stems: all points of the slice split by single-linkage on a horizontal
// grid (cells of link_m, 8-neighbourhood); several large ones are several trees in one cloud.
#include <cstddef>
#include <optional>
#include <vector>

#include "scans/circle_fit.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

struct BreastHeightOptions {
  double slice_low_m = 1.2;  // above the lowest point
  double slice_high_m = 1.4;
  std::size_t min_points = 20;  // fewer trunk points in the slice: no diameter
  double max_diameter_m = 5.0;
  double stem_low_m = 0.0;  // the slice at the foot
  double stem_high_m = 0.2;
  double base_low_m = 0.3;  // the slice where stems are counted
  double base_high_m = 0.6;
  double link_m = 0.1;  // points closer than about this belong to one stem
};

struct BreastHeightStem {
  std::size_t slice_points = 0;  // trunk points in the slice
  std::optional<Circle> circle;  // when there are at least min_points
  bool compact = false;
};

// The trunk points (`on_trunk[i]`: point i belongs to the trunk) from low_m to high_m above
// ground_z and their circle.
BreastHeightStem stem_slice(const PointSet& points, const std::vector<char>& on_trunk,
                            double ground_z, double low_m, double high_m,
                            const BreastHeightOptions& options = {});

// Points of each stem in the base slice with at least min_points and a fifth of the largest
// stem's points, largest first.
std::vector<std::size_t> stems_at_base(const PointSet& points, double ground_z,
                                       const BreastHeightOptions& options = {});

}  // namespace fspm::scans
