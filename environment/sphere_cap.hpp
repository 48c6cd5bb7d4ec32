#pragma once
// A sphere (a leaf cluster) seen from a point as a spherical cap of its sky: the occluder type of
// LightModel (per point) and ClusterLightField (per leaf cluster), read by analytic_caps.hpp and
// sky_occlusion_kernel.hpp.
#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace fspm::environment {

struct SphereCap {
  Eigen::Vector3d axis;  // unit, from the point to the sphere's centre
  double cos_a;          // of the half angle
  double sin_a;
  double gamma;  // translucency
};

// Adds a sphere of radius r and translucency gamma at offset d (squared length d2) from a point:
// a point inside it sees it across every direction (`all` takes gamma), one outside it as a cap.
inline void add_sphere_occluder(const Eigen::Vector3d& d, double d2, double r, double gamma,
                                double& all, std::vector<SphereCap>& caps) {
  const double r2 = r * r;
  if (d2 <= r2) {
    all *= gamma;  // every ray from inside crosses the cluster
    return;
  }
  const double dist = std::sqrt(d2);
  caps.push_back({d / dist, std::sqrt(d2 - r2) / dist, r / dist, gamma});
}

}  // namespace fspm::environment
