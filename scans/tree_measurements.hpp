#pragma once
// Forest measurements of a scanned tree, as a quantitative structure model reports them (TreeQSM,
// Raumonen et al. 2013), from its points and its skeleton:
// - dbh_m: diameter of the circle fitted to the trunk points at breast height
//   (scans/breast_height.hpp), unset when the slice has too few of them, no compact stem, or
//   two or more separate stems (a fork below breast height: breast_height_stems_m);
// - height_m: highest minus lowest point;
// - crown_base_m: height above the lowest point of the base of the lowest branch on the trunk
//   that carries at least min_branch_length_m of skeleton (the lowest live branch's base:
//   the crown base in the silvicultural sense; scans/crown_base.hpp);
// - crown_width_m: the mean of the x and y extents of the points above the crown base (all
//   points when no crown base is found);
// - woody_volume_m3, branches_per_order, branch_length_per_order_m: from cylinders fitted along
//   the skeleton (scans/qsm_cylinders.hpp); a branch is a chain of skeleton nodes of one order;
// - points_explained_fraction: share of points within explained_tolerance_m of the surface of
//   their nearest cylinder.
// Warnings (text that says what was found and what to do) for too few trunk points at breast
// height, no compact stem there (no tree found: a wall, a hedge), a flat vertical surface of many
// square metres (a building: no tree found without a stem), several stems near the base,
// and a diameter implausible for the height. Projected coordinates are recentred internally;
// cylinders come back in the input's coordinates.
#include <optional>
#include <string>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/breast_height.hpp"
#include "scans/point_set.hpp"
#include "scans/qsm_cylinders.hpp"
#include "scans/vertical_plane.hpp"

namespace fspm::scans {

struct MeasureOptions {
  BreastHeightOptions breast_height;
  double explained_tolerance_m = 0.02;
  double min_branch_length_m = 0.5;
  // A dbh above this fraction of the height is reported as implausible.
  double max_dbh_per_height = 0.2;
  // A flat vertical surface this large is a wall (scans/vertical_plane.hpp); the trees of the
  // public scans checked (docs/scans.md) have at most 6 m2, a house's wall 20 m2.
  VerticalPlaneOptions wall;
  double min_wall_area_m2 = 12.0;
};

struct TreeMeasurements {
  std::optional<double> dbh_m;
  double height_m = 0.0;
  double crown_width_m = 0.0;
  std::optional<double> crown_base_m;
  double woody_volume_m3 = 0.0;
  std::vector<std::size_t> branches_per_order;
  std::vector<double> branch_length_per_order_m;
  double points_explained_fraction = 0.0;
  std::size_t breast_height_points = 0;  // trunk points in the breast-height slice
  std::size_t stems = 0;                 // separated stems near the base
  // The diameters of the separate stems at breast height when there are two or more (a fork
  // below it, or several trees); dbh_m is then unset.
  std::vector<double> breast_height_stems_m;
  bool tree_found = false;  // a compact stem at breast height, or too few points to tell
  std::vector<std::string> warnings;
  std::vector<QsmCylinder> cylinders;
};

// `skeleton`: the encoder's full skeleton with branching orders (EncodeResult::full_skeleton).
// Throws ValueError for an empty point set or skeleton.
TreeMeasurements measure_tree(const PointSet& points, const TreeGraph& skeleton,
                              const MeasureOptions& options = {});

}  // namespace fspm::scans
