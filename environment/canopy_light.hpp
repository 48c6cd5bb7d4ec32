#pragma once
// Light of leaf clusters inside a crown: the clusters are turbid media (Monsi and Saeki 1953;
// Campbell and Norman 1998, ch. 15) and a sky ray is attenuated by Beer-Lambert along the path it
// travels inside each of them, T = exp(-mu * s), instead of once per sphere it touches.
//
// Why: a crown's clusters overlap, so a cluster's centre lies inside several neighbours. Pirk's
// eq. 4.3 multiplies a ray by a sphere's whole translucency gamma whenever it crosses the sphere,
// so a point inside n spheres receives at most gamma^n from every direction, the top of the crown
// as much as its bottom. Along a path, a point inside a sphere is shaded only by the leaves
// between it and the sphere's surface in each direction.
//
// The extinction coefficient of a cluster is chosen so that a diametral chord transmits Pirk's
// eq. 4.4 translucency: exp(-mu * 2 r) = gamma, mu = -ln(gamma) / (2 r); for gamma = gamma0^r it
// is the same for every cluster, -ln(gamma0) / 2 per metre. With leaves of spherical angle
// distribution (projection G = 0.5, Campbell and Norman eq. 15.4) the cluster holds a leaf area
// density LAD = mu / G, so its leaf area is LAD * 4/3 pi r^3.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "environment/hemisphere.hpp"
#include "environment/leaf_area_grid.hpp"
#include "environment/light_model.hpp"
#include "environment/scene.hpp"

namespace fspm::environment {

// Projection of a unit leaf area on a plane normal to the ray for a spherical leaf angle
// distribution (Campbell and Norman 1998, eq. 15.4 with x = 1).
inline constexpr double kSphericalLeafProjection = 0.5;

// Extinction coefficient mu (1/m) of a cluster whose diametral chord transmits `translucency`
// (inf for an opaque cluster, 0 for a fully transparent one).
double cluster_extinction_per_m(const Sphere& cluster);
// Leaf area (m^2) of a cluster with spherical leaf angles: mu / G * 4/3 pi r^3.
double cluster_leaf_area_m2(const Sphere& cluster);
// The top of a cluster's sphere, the part of the cluster that faces the sky: the light of its
// best-lit leaves (every ray of the upper hemisphere leaves the cluster's own sphere there at
// once).
inline Eigen::Vector3d cluster_top(const Sphere& cluster) {
  return cluster.center + cluster.radius_m * Eigen::Vector3d::UnitZ();
}

class CanopyLight {
 public:
  // The scene gives the sky (directions, brightest point, significance) and the obstacles (its
  // boxes, meshes, ground and spheres, each attenuating a ray by its translucency once as in
  // eq. 4.3); `clusters` are the leaf clusters, attenuating by path length.
  // With voxel_m > 0 the clusters' extinction is binned in voxels of that size (LeafAreaGrid) and
  // rays with no cluster left out march through them: much faster in a large crown, at the cost
  // of the voxels' resolution. Leaving a cluster out (`ignore`) always follows the spheres.
  CanopyLight(const Scene& scene, std::span<const Sphere> clusters, double voxel_m = 0.0);

  // Light at p relative to the open sky (cos^2 sky of eq. 4.3 over the stratified directions),
  // leaving out cluster `ignore` (an index into clusters), and its mean direction.
  LightSample evaluate(const Eigen::Vector3d& p, std::uint32_t ignore = kNoSphere) const;
  // The mean light of each cluster's leaves: the light at its centre with its own leaves shading
  // it (a path of one radius in every direction). Over leaves spread uniformly in the sphere the
  // light's mean is close to its value at the centre; checked against ray-traced leaves
  // (tests/environment/light_yardstick_test.cpp, docs/environment.md).
  std::vector<LightSample> evaluate_clusters() const;
  // The light of each cluster's best-lit leaves, at its top (cluster_top), its own left out.
  std::vector<LightSample> evaluate_cluster_tops() const;

  // Transmission of the sky's light to p per direction of directions() (clusters by path length,
  // obstacles by translucency), and along one unit direction d (the sun's), leaving out `ignore`.
  void transmission(const Eigen::Vector3d& p, std::uint32_t ignore, std::vector<double>& out) const;
  double transmission_along(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                            std::uint32_t ignore = kNoSphere) const;
  // transmission_along for many points and one direction (the sun's at one hour): the clusters
  // are binned once by their shadow on the plane normal to d, so each point meets only the
  // clusters whose shadow covers its own. ignore[k] (if given) is left out at point k.
  void transmission_along(std::span<const Eigen::Vector3d> points, const Eigen::Vector3d& d,
                          std::span<const std::uint32_t> ignore, std::span<double> out) const;

  // Cumulative leaf area index above p (m^2 of leaf per m^2 of ground): the leaf area density of
  // the clusters integrated along the vertical ray up from p, leaving out cluster `ignore`.
  double leaf_area_index_above(const Eigen::Vector3d& p, std::uint32_t ignore = kNoSphere) const;

  // The leaf area above p as the sky sees it: per direction d the leaf area index a horizontal
  // layer would need to hold the leaves along d (G L_d / cos(theta_d) = optical depth, so
  // L_d = tau_d cos(theta_d) / G), averaged with the sky's weights I(d). In a horizontally
  // uniform stand every L_d is the leaf area index above p (Monsi and Saeki's abscissa); in an
  // isolated crown it counts the open sides.
  double sky_leaf_area_index_above(const Eigen::Vector3d& p,
                                   std::uint32_t ignore = kNoSphere) const;

  const HemisphereDirections& directions() const { return dirs_; }

 private:
  void accumulate_depth(const Eigen::Vector3d& p, std::uint32_t ignore,
                        std::vector<double>& depth) const;
  void obstacle_visibility(const Eigen::Vector3d& p, std::vector<double>& vis) const;
  double obstacle_transmission(const Eigen::Vector3d& p, const Eigen::Vector3d& d) const;

  std::optional<LeafAreaGrid> grid_;
  Scene obstacles_;
  bool has_obstacles_ = false;
  std::vector<Sphere> clusters_;
  std::vector<double> mu_;      // extinction per metre
  std::vector<double> reach2_;  // squared shadow reach (significance cutoff)
  HemisphereDirections dirs_;
  std::vector<double> weight_;  // I(d)
  double weight_sum_ = 0.0;
  Eigen::Vector3d open_direction_ = Eigen::Vector3d::UnitZ();
};

}  // namespace fspm::environment
