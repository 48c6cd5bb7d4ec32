#pragma once
// The largest flat vertical surface of a point set: a wall or a facade, which no tree has. Planes
// are found by a Hough transform over vertical planes (Vosselman et al. 2004): each point votes,
// for every horizontal normal direction theta, for the offset d = n(theta) . (x, y) of the plane
// through it. A candidate slab is then cut into cells (along the plane x height); a cell is flat
// when the slab holds most of the points near the plane in that cell, so a roof above a wall, a
// slice through a crown or the side of a trunk is not counted. Points near the lowest point
// (ground) are left out.
#include <cstddef>
#include <optional>

#include "scans/point_set.hpp"

namespace fspm::scans {

struct VerticalPlaneOptions {
  double thickness_m = 0.1;        // slab width (scan noise and half-degree steps of theta)
  double neighbourhood_m = 0.5;    // points this near the plane are compared with the slab's
  double min_flatness = 0.7;       // slab points / near points of a flat cell
  double cell_m = 0.5;             // cells along the plane x height
  double ground_m = 0.5;           // points this near the lowest point are left out
  std::size_t max_points = 50000;  // a larger set votes with an even subsample
  int directions = 180;            // theta steps over 180 degrees
  int candidates = 4;              // fullest peaks of the votes examined per direction
};

struct VerticalPlane {
  double area_m2 = 0.0;  // flat cells x cell area
  double share = 0.0;    // of the (subsampled, above-ground) points in its flat cells
};

// The vertical plane with the largest flat area; none when no cell is flat. Deterministic.
std::optional<VerticalPlane> largest_vertical_plane(const PointSet& points,
                                                    const VerticalPlaneOptions& options = {});

}  // namespace fspm::scans
