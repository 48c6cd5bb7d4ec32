#pragma once
// The stem at breast height, as foresters measure DBH: the points in a horizontal slice 1.2-1.4 m
// above the lowest point, split into stems by single-linkage on a horizontal grid (cells of
// link_m, 8-neighbourhood), and a circle fitted to the horizontal positions of the largest stem
// (Kasa 1976, scans/circle_fit.hpp). A stem is compact when its points lie on a circle (rms
// below a fifth of the radius plus 5 mm) of diameter at most max_diameter_m: a wall, a hedge or
// a crown reaching down is not.
#include <cstddef>
#include <optional>
#include <vector>

#include "scans/circle_fit.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

struct BreastHeightOptions {
  double slice_low_m = 1.2;  // above the lowest point
  double slice_high_m = 1.4;
  double link_m = 0.1;          // points closer than about this belong to one stem
  std::size_t min_points = 20;  // fewer in the slice: no diameter
  double max_diameter_m = 5.0;
};

struct BreastHeightStems {
  std::size_t slice_points = 0;
  // Stems with at least min_points and a fifth of the largest stem's points, largest first.
  std::vector<std::size_t> stem_points;
  std::optional<Circle> circle;  // of the largest stem, when it has at least min_points
  bool compact = false;
};

BreastHeightStems breast_height_stems(const PointSet& points, double ground_z,
                                      const BreastHeightOptions& options = {});

}  // namespace fspm::scans
