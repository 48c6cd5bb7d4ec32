#pragma once
// A simulated terrestrial laser scan of a tree whose skeleton is known, for validating the
// encoder against a known answer. Every internode is a cylinder (its segment and radius). From
// each of `scanners` positions on a circle around the tree base, at scanner height, points are
// drawn on the cylinder surfaces with the density a scanner of fixed angular step produces
// (proportional to |cos incidence| / range^2, `density_per_m2` at the circle's radius and normal
// incidence) and kept only where the scanner sees them: the surface faces it and no other
// cylinder crosses the line of sight. Each kept point is moved along its line of sight by a
// Gaussian range error of `range_noise_m`. Leaves, flowers and buds are not scanned.
#include <random>

#include "fspm/tree_graph.hpp"
#include "scans/point_set.hpp"

namespace fspm::scans {

struct ScanOptions {
  int scanners = 4;
  double distance_factor = 1.5;     // circle radius = factor * tree height (at least 1 m)
  double scanner_height_m = 1.5;    // above the tree base
  double density_per_m2 = 20000.0;  // at the circle radius and normal incidence
  double range_noise_m = 0.003;
  double min_radius_m = 0.0;  // thinner internodes are not scanned

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// Throws ValueError for options out of range (ScanOptions::validate). Draws from `rng` only.
PointSet simulate_scan(const TreeGraph& tree, const ScanOptions& options, std::mt19937_64& rng);

// Scanner positions the simulation uses (for documentation and tests).
std::vector<Eigen::Vector3d> scanner_positions(const TreeGraph& tree, const ScanOptions& options);

}  // namespace fspm::scans
