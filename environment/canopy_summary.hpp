#pragma once
// What a physiologist reports of a crown's foliage under a beam of direct light: its leaf area,
// the part of it in the sun and in the shade, its silhouette and the silhouette to total area
// ratio (STAR, Oker-Blom and Smolander 1988), with the leaf clusters as turbid media of spherical
// leaf angles (canopy_light.hpp).
//
// The silhouette is the area the foliage takes from the beam: S = integral over the plane normal
// to the beam of (1 - T), T the transmission of the line through the crown. A unit of sunlit leaf
// area intercepts G = 0.5 units of the beam's cross-section (spherical leaf angles), so the sunlit
// leaf area is S / G (Campbell and Norman 1998, ch. 15: L_sun = (1 - exp(-K L)) / K for a
// horizontal canopy) and STAR = S / L = G times the sunlit share: 0.5 for leaves that do not
// shade each other, less in a dense crown.
#include <Eigen/Core>
#include <cstddef>
#include <span>

#include "environment/occluders.hpp"

namespace fspm::environment {

struct CanopySummary {
  std::size_t clusters = 0;
  double leaf_area_m2 = 0.0;  // one-sided, cluster_leaf_area_m2 summed
  double sunlit_leaf_area_m2 = 0.0;
  double shaded_leaf_area_m2 = 0.0;
  double silhouette_area_m2 = 0.0;
  double star = 0.0;  // silhouette / leaf area
};

// The beam comes from unit direction `sun` (toward the sun); the silhouette is sampled on a square
// grid of `pixel_m` on the plane normal to it. Throws ValueError unless pixel_m > 0.
CanopySummary summarize_canopy(std::span<const Sphere> clusters,
                               const Eigen::Vector3d& sun = Eigen::Vector3d::UnitZ(),
                               double pixel_m = 0.02);

}  // namespace fspm::environment
