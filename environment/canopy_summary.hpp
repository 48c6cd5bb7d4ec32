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
#include <vector>

#include "environment/occluders.hpp"
#include "environment/scene.hpp"
#include "environment/sky.hpp"

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

namespace fspm::environment {

// Leaf absorptance for PAR (Campbell and Norman 1998, ch. 15: a_p = 0.8).
inline constexpr double kLeafParAbsorptance = 0.8;

// The light of each leaf cluster's leaves in the crown, as a physiologist reports it, with the
// clusters as turbid media swept in voxels (CanopySweep, kCanopySweepVoxel_m) and T_c(d) the
// transmission from the cluster's centre toward d (its own leaves included):
//   sunlit fraction f_c = sum_t S_b(t) T_c(s_t) / sum_t S_b(t) over the sun's positions (a beam
//     from the zenith without a real sky); in a horizontally homogeneous canopy exp(-K L) at a
//     depth of leaf area index L (Campbell and Norman 1998, eq. 15.21; de Pury and Farquhar 1997);
//   light interception efficiency LIE_c = sum_d F_d T_c(d) / sum_d F_d, F_d the light of direction
//     d on a plane normal to it (the sky's weight on a horizontal plane over cos theta): the
//     light the leaves intercept against leaves of the same area without shade (1);
//   STAR_c = G LIE_c: the silhouette the leaves cast, per leaf area, averaged over the sky (0.5
//     for unshaded leaves of spherical angles, G = 0.5);
//   absorbed PAR (real sky only): a_p G LA_c sum_d F_d T_c(d), mol per day.
struct ClusterCanopyLight {
  double leaf_area_m2 = 0.0;
  double sunlit_fraction = 0.0;
  double sunlit_leaf_area_m2 = 0.0;
  double shaded_leaf_area_m2 = 0.0;
  double lie = 0.0;
  double star = 0.0;
  double absorbed_par_mol_day = 0.0;  // 0 without a real sky
};

// The crown's totals: sums of the clusters' areas and absorbed PAR, LIE and STAR weighted by
// leaf area.
struct CanopyLightSummary {
  std::size_t clusters = 0;
  double leaf_area_m2 = 0.0;
  double sunlit_leaf_area_m2 = 0.0;
  double shaded_leaf_area_m2 = 0.0;
  double lie = 0.0;
  double star = 0.0;
  double absorbed_par_mol_day = 0.0;
  bool real_sky = false;  // absorbed PAR given (sky.distribution)
  std::vector<ClusterCanopyLight> per_cluster;
};

// Under `sky`: its real sky's sun positions and diffuse light (sky.distribution, with
// sky.directions diffuse directions), or the cos^2 sky of eq. 4.3 and a beam from the zenith.
// The crown's own light, without obstacles.
CanopyLightSummary summarize_canopy_light(std::span<const Sphere> clusters, const Sky& sky);
// Under scene.sky, with the scene's obstacles (not its leaf clusters: scene.spheres count as
// obstacles) by their translucency along each direction, as eq. 4.3 takes them.
CanopyLightSummary summarize_canopy_light(std::span<const Sphere> clusters, const Scene& scene);

}  // namespace fspm::environment
