#pragma once
// The sky integral of Pirk eq. 4.3 (I = cos^2 of the angle to the brightest point b) in closed
// form, for occluders seen as spherical caps that lie whole above the horizon and do not overlap;
// shared by LightModel (per point) and ClusterLight (per leaf cluster). A cap type needs the
// members axis (unit), cos_a, sin_a (of its half angle) and gamma (translucency).
#include <Eigen/Core>
#include <cstddef>
#include <numbers>
#include <span>

namespace fspm::environment {

// At most this many caps are evaluated in closed form (the overlap test is quadratic in them).
inline constexpr std::size_t kMaxAnalyticCaps = 16;

// True when every cap lies above the horizon (elevation of its axis >= its half angle) and no two
// overlap (angle between axes >= the sum of the half angles): the closed form is then exact.
template <class Cap>
bool analytic_caps_exact(std::span<const Cap> caps) {
  for (std::size_t i = 0; i < caps.size(); ++i) {
    if (caps[i].axis.z() < caps[i].sin_a) return false;
    for (std::size_t j = 0; j < i; ++j) {
      const double cos_sum = caps[i].cos_a * caps[j].cos_a - caps[i].sin_a * caps[j].sin_a;
      if (caps[i].axis.dot(caps[j].axis) > cos_sum) return false;
    }
  }
  return true;
}

struct AnalyticLight {
  double integral = 0.0;                             // integral of I V over the hemisphere
  double open_integral = 0.0;                        // the same without occluders (2 pi / 3)
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // integral of I V d (unnormalized)
};

// Closed forms over the hemisphere: the integral of (b.d)^2 is 2 pi / 3, and of (b.d)^2 d is
// (pi/2 bx bz, pi/2 by bz, pi/4 (bx^2 + by^2) + pi/2 bz^2). Over a cap of half angle alpha
// around c, with beta = b.c and a = cos alpha:
//   F = 2 pi beta^2 (1 - a^3)/3 + pi (1 - beta^2) ((1 - a) - (1 - a^3)/3),
//   M = (2 pi beta^2 A + pi (1 - beta^2) B) c + 2 pi beta B (b - beta c),
// with A = (1 - a^4)/4 and B = (1 - a^2)^2 / 4. Each cap removes (1 - gamma) of its F and M.
template <class Cap>
AnalyticLight analytic_cap_light(const Eigen::Vector3d& b, std::span<const Cap> caps) {
  constexpr double pi = std::numbers::pi;
  const double total = 2.0 * pi / 3.0;
  double f = total;
  Eigen::Vector3d m(0.5 * pi * b.x() * b.z(), 0.5 * pi * b.y() * b.z(),
                    0.25 * pi * (b.x() * b.x() + b.y() * b.y()) + 0.5 * pi * b.z() * b.z());
  for (const Cap& c : caps) {
    const double beta = b.dot(c.axis);
    const double a = c.cos_a;
    const double a3 = a * a * a;
    const double cap_f = 2.0 * pi * beta * beta * (1.0 - a3) / 3.0 +
                         pi * (1.0 - beta * beta) * ((1.0 - a) - (1.0 - a3) / 3.0);
    const double big_a = 0.25 * (1.0 - a3 * a);
    const double big_b = 0.25 * (1.0 - a * a) * (1.0 - a * a);
    const Eigen::Vector3d cap_m =
        (2.0 * pi * beta * beta * big_a + pi * (1.0 - beta * beta) * big_b) * c.axis +
        2.0 * pi * beta * big_b * (b - beta * c.axis);
    f -= (1.0 - c.gamma) * cap_f;
    m -= (1.0 - c.gamma) * cap_m;
  }
  return {f, total, m};
}

}  // namespace fspm::environment
