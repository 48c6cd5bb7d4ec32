#pragma once
// Test oracle, independent of LightModel: midpoint quadrature over (theta, phi) of the upper
// hemisphere of (b.d)^2 V(d) and (b.d)^2 V(d) d, with V supplied by the test.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace fspm::environment::testing {

struct SkyIntegral {
  double integral = 0.0;                             // of (b.d)^2 V
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // of (b.d)^2 V d
  double open = 0.0;                                 // of (b.d)^2 (V = 1)
  double light() const { return integral / open; }
};

template <class Visibility>
SkyIntegral sky_quadrature(const Eigen::Vector3d& b, int n_theta, int n_phi,
                           Visibility&& visibility) {
  const double pi = std::numbers::pi;
  const double dt = 0.5 * pi / n_theta, dp = 2.0 * pi / n_phi;
  SkyIntegral out;
  for (int i = 0; i < n_theta; ++i) {
    const double theta = (i + 0.5) * dt;
    const double st = std::sin(theta), ct = std::cos(theta);
    const double area = st * dt * dp;
    for (int j = 0; j < n_phi; ++j) {
      const double phi = (j + 0.5) * dp;
      const Eigen::Vector3d d(st * std::cos(phi), st * std::sin(phi), ct);
      const double w = b.dot(d) * b.dot(d) * area;
      const double v = visibility(d);
      out.open += w;
      out.integral += w * v;
      out.moment += (w * v) * d;
    }
  }
  return out;
}

// Ray from p along d against an oriented box (centre, half extents, rotation columns = axes):
// slab test in the box frame, written here so the oracle does not share LightModel's code.
inline bool ray_meets_box(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                          const Eigen::Vector3d& center, const Eigen::Vector3d& half,
                          const Eigen::Matrix3d& rotation) {
  double lo = 0.0, hi = 1e300;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = rotation.col(k);
    const double o = axis.dot(p - center), v = axis.dot(d);
    if (std::abs(v) < 1e-300) {
      if (std::abs(o) > half[k]) return false;
      continue;
    }
    double t0 = (-half[k] - o) / v, t1 = (half[k] - o) / v;
    if (t0 > t1) std::swap(t0, t1);
    lo = std::max(lo, t0);
    hi = std::min(hi, t1);
  }
  return lo <= hi;
}

inline bool ray_meets_sphere(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                             const Eigen::Vector3d& center, double r) {
  const Eigen::Vector3d c = center - p;
  const double along = c.dot(d);
  return along > 0.0 && c.squaredNorm() - along * along < r * r;
}

}  // namespace fspm::environment::testing
