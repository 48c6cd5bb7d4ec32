#pragma once
// Light of leaf clusters from Palubicki's shadow grid (shadow_grid.hpp), for the analysis and the
// plastic adaptation of a tree grown with the same local light (Palubicki et al. 2009, 4.1). Every
// tip of a living cluster is a bud that casts shade into the pyramid below it; a cluster's light
// is the mean Q / C of its buds (each without its own shade) and its light direction is the
// zenith tilted toward the less shaded side (ShadowGrid::light_direction). Obstacles are voxels,
// as in growth; the adaptation also takes the sky they hide from each cluster
// (combine_sky_and_grid), which the grid's local shade alone would miss beyond q_max voxels.
// Under a real sky (Scene::sky.distribution) the pyramids lean along the sky's PAR-weighted mean
// direction as growth's do (ShadowGrid::set_light_direction), and a cluster's direction is its
// tilt toward the less shaded side about the zenith, the lean being in the sky's direction that
// combine_sky_and_grid adds it to.
//
// The grid is coarser than the growth model's so that it can be filled and propagated again at
// every age level of an adaptation (see cluster_grid_params). Unlike growth, which places a bud
// in its voxel as Palubicki does, the cluster light spreads each bud over the eight nearest voxel
// centres and interpolates its light (ShadowGrid::add_bud_spread): an adaptation moves buds by
// fractions of a voxel, and with the nearest voxel a bud's light jumps by up to a / C as it
// crosses a voxel face; the adaptation's feedback (bend, read the light again, bend again) turned
// those jumps into bends and pruning far from any obstacle.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "environment/scene.hpp"
#include "environment/shadow_grid.hpp"

namespace fspm::environment {

// A cluster's light and direction from the share `sky` of the sky's light it sees past the
// obstacles (mean direction `sky_direction`) and from its shade in the grid (`light`,
// `direction` as ClusterGridLight gives them, replaced by the result): the shares multiply (the
// foliage and the obstacles are taken to block independent parts of the sky) and the grid's tilt
// toward the less shaded side is added to the sky's direction.
inline void combine_sky_and_grid(double sky, const Eigen::Vector3d& sky_direction, double& light,
                                 Eigen::Vector3d& direction) {
  light *= sky;
  const Eigen::Vector3d tilt(direction.x() / direction.z(), direction.y() / direction.z(), 0.0);
  direction = (sky_direction + tilt).normalized();
}

// Default grid of the cluster light: the growth model's default grid made twice as coarse, its
// shade per bud and per obstacle voxel fitted to give the clusters the fine grid's light.
ShadowGridParams cluster_grid_params();

class ClusterGridLight {
 public:
  // Throws ValueError for invalid grid parameters.
  ClusterGridLight(const ShadowGridParams& params, const Scene& scene);
  ~ClusterGridLight();
  ClusterGridLight(const ClusterGridLight&) = delete;
  ClusterGridLight& operator=(const ClusterGridLight&) = delete;

  // Buds of cluster c: buds[bud_start[c] .. bud_start[c + 1]). Clusters with alive[c] == 0 cast
  // no shade and keep their light. Writes light[c] in [0, 1] and the unit direction[c] (under a
  // real sky the tilt about the zenith, see above).
  void evaluate(std::span<const Eigen::Vector3d> buds, std::span<const std::uint32_t> bud_start,
                std::span<const Eigen::Vector3d> centers, std::span<const std::uint8_t> alive,
                std::span<double> light, std::span<Eigen::Vector3d> direction);

 private:
  void fit(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

  // Taken from a per-thread pool and given back: touching fresh memory costs more than an
  // adaptation on virtual machines, and experiments adapt thousands of trees in turn.
  std::unique_ptr<ShadowGrid> grid_;
  const Scene& scene_;
  bool sized_ = false;
  bool leaning_ = false;  // the scene has a real sky: the pyramids lean along its mean direction
  std::vector<ShadowGrid::Corners> corners_;  // per bud, reused between evaluations
  std::vector<std::uint8_t> located_;
};

}  // namespace fspm::environment
