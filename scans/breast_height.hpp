#pragma once
// The stem as foresters measure it. At breast height, the trunk's points (those nearest to the
// skeleton's order-0 axis) in a horizontal slice 1.2-1.4 m above the lowest point, and a circle
// fitted across the stem's axis for the DBH (stem_section below). The same fit on a slice at
// the foot (stem_low_m, stem_high_m) tells a tree forked below breast height (a compact stem
// there) from no tree at all. Near the base (0.3-0.6 m), the stems: all points of the slice
// split by single-linkage on a horizontal grid (cells of link_m, 8-neighbourhood); several large
// ones are several trees in one cloud.
//
// A stem section (stem_section): the stem's lean from the circles of the slice's lower and upper
// halves (their centres lie on the axis), the points projected onto the plane across that axis
// (a horizontal slice of a leaning stem is an ellipse, and its points are smeared by the slice's
// thickness times the lean; the lean is kept where its section's median residual is at most 90 %
// of a vertical axis's, since on a sparse one-sided arc the halves' circles are noise), and a
// robust circle there (Kasa 1976 reweighted by Tukey's
// biweight, scans/circle_fit.hpp; Pueschel et al. 2013 fit stem circles in such slices). The
// section is compact, a stem, when its median |residual| is small beside its radius, at least
// half its points are inliers, its inliers cover an arc of at least min_sectors of 12 sectors,
// its diameter is at most max_diameter_m and its lean at most max_lean_deg: a wall, a hedge, a
// crown reaching down or leaves are not.
//
// A fork below breast height (stems_at_breast_height): the slice's points (all of them, since the
// skeleton's trunk follows one stem only) split into groups (single linkage, slice_link_m), a
// section fitted to each group and, where a group holds two touching stems, to its outliers; the
// compact sections whose girth holds over the slice's height (max_radius_change), whose inliers
// cover an unbroken arc of at least min_stem_arc_deg, that do not
// overlap a thicker one and are at least codominant_share of the thickest one's diameter are
// separate stems (codominant stems, as foresters call the stems of
// a fork that are each measured as a tree).
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
  // Stem sections.
  double slice_link_m = 0.05;  // points of one stem in the breast-height slice
  int min_sectors = 4;         // of 12: an arc of at least a third of the stem
  // Median |residual| at most this share of the radius, at most max_residual_m, plus
  // residual_floor_m (bark, noise, misregistered scans): bark furrows do not deepen without
  // bound with the stem's girth, and a wall's points lie metres off any circle.
  double max_residual_share = 0.15;
  double max_residual_m = 0.03;
  double residual_floor_m = 0.005;
  double min_inlier_share = 0.5;
  double max_lean_deg = 45.0;
  double codominant_share = 0.5;  // of the thickest stem's diameter
  // A separate stem's radius changes by at most this per metre of height between the circles of
  // the slice's halves (a whorl of branches widens as fast as they lean out).
  double max_radius_change = 0.1;
  // ... and its inliers cover an unbroken arc of at least this (branches crossing the slice hit a
  // circle at scattered angles).
  double min_stem_arc_deg = 90.0;
  // The stems of a fork carry no more wood than the stem below them (the pipe model: the sum of
  // their squared diameters at most that of the foot's diameter times this, which leaves room for
  // noise; a root flare only widens the foot).
  double max_fork_to_foot = 1.25;
};

struct StemSection {
  std::size_t points = 0;        // in the slice
  std::optional<Circle> circle;  // across the axis; centre: the axis at the slice's mean height
  std::size_t inliers = 0;
  int sectors = 0;               // of 12 holding inliers
  double longest_arc_deg = 0.0;  // the longest unbroken arc of inliers (sectors of 10 degrees)
  double median_residual_m = 0.0;
  double lean_deg = 0.0;  // of the axis from the vertical
  // From the circle of the slice's lower half to its upper half's; unset without them.
  std::optional<double> radius_change_per_m;
  bool compact = false;
  std::vector<char> inlier;  // per point given
};

// The section of a stem through `points` (a slice of it, z up), as described above.
StemSection stem_section(const std::vector<Eigen::Vector3d>& points,
                         const BreastHeightOptions& options = {});

// The trunk points (`on_trunk[i]`: point i belongs to the trunk) from low_m to high_m above
// ground_z and their section.
StemSection stem_slice(const PointSet& points, const std::vector<char>& on_trunk, double ground_z,
                       double low_m, double high_m, const BreastHeightOptions& options = {});

// The separate codominant stems of the breast-height slice (all points), thickest first; two or
// more: the tree forks below breast height, or the cloud holds several trees.
std::vector<StemSection> stems_at_breast_height(const PointSet& points, double ground_z,
                                                const BreastHeightOptions& options = {});

// Points of each stem in the base slice with at least min_points and a fifth of the largest
// stem's points, largest first.
std::vector<std::size_t> stems_at_base(const PointSet& points, double ground_z,
                                       const BreastHeightOptions& options = {});

}  // namespace fspm::scans
