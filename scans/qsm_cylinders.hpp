#pragma once
// Cylinders along a tree skeleton fitted to the scanned points, as a quantitative structure model
// (QSM; TreeQSM, Raumonen et al. 2013) describes a tree: one cylinder per skeleton segment. Each
// point goes to the segment nearest to it; a segment's points are projected onto the plane
// across its axis and a circle is fitted to them (Kasa 1976, scans/circle_fit.hpp), which gives
// the radius and moves the axis from the centroid of the (often one-sided) surface points to the
// circle's centre. A fit that is poor (rms above a sixth of the radius, fewer than 5 points) is
// replaced by the smaller of the median distance of the points from the axis and the radius the
// pipe model carries from the nearest fitted ancestor a, r_a sqrt(L(u) / L(a)) with L the
// skeleton length a segment carries (Shinozaki et al. 1964): in a leafy crown the median
// distance is the spread of the leaves. As in TreeQSM, a branch cylinder is
// never wider than its parent (nor is a trunk cylinder without a circle fit: the scattered points
// of a crown top), the first cylinder of a branch is fitted to its points off the parent's
// surface, and one whose axis middle lies inside a wider cylinder is marked nested
// and left out of the volume, so that a skeleton that runs twice along a stem does not count its
// wood twice.
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

struct QsmCylinder {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();  // unit
  double length_m = 0.0;
  double radius_m = 0.0;
  std::int64_t parent = -1;  // index of the parent cylinder, -1 for the first
  std::int64_t branch = 0;   // index of the branch (a chain of one order), 0 for the trunk
  int order = 0;             // branching order, 0 for the trunk
  // The middle of the axis lies inside a wider cylinder (a skeleton running twice along one
  // stem, or pieces of a stem's ring at a fork): not counted in the volume.
  bool nested = false;
};

struct QsmCylinders {
  std::vector<QsmCylinder> cylinders;            // one per skeleton node, in node order
  std::vector<std::uint32_t> cylinder_of_point;  // nearest segment of each point
  std::vector<double> surface_distance_m;        // |distance from the axis - radius| per point
};

// `skeleton` with branching orders set (scans/allometry.hpp, set_branch_orders). Points and
// skeleton in the same coordinates; callers recentre projected coordinates first
// (scans/point_origin.hpp). Throws ValueError for an empty skeleton.
QsmCylinders fit_qsm_cylinders(const PointSet& points, const TreeGraph& skeleton);

// Volume of the cylinders that are not nested, pi r^2 l summed (m^3).
double cylinders_volume_m3(const std::vector<QsmCylinder>& cylinders);

}  // namespace fspm::scans
