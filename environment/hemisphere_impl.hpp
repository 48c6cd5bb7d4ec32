#pragma once
// Inline cap rasterization for HemisphereDirections (hot loop of the light model).
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fspm::environment {
namespace detail {

// Fast arc functions for the cap's cell range only; membership is decided by an exact dot
// product, and the range is widened by a cell, so their small error (< 1e-4 rad) is harmless.
inline double fast_atan2(double y, double x) {
  const double ax = std::abs(x), ay = std::abs(y);
  const double mx = std::max(ax, ay);
  if (mx == 0.0) return 0.0;
  const double a = std::min(ax, ay) / mx;
  const double s = a * a;
  double r = ((-0.0464964749 * s + 0.15931422) * s - 0.327622764) * s * a + a;
  if (ay > ax) r = 1.57079637 - r;
  if (x < 0) r = 3.14159274 - r;
  return y < 0 ? -r : r;
}

inline double fast_acos(double x) {  // Abramowitz and Stegun 4.4.45, |error| <= 7e-5
  const double ax = std::abs(x);
  const double r =
      std::sqrt(1.0 - ax) * (1.5707288 + ax * (-0.2121144 + ax * (0.0742610 - 0.0187293 * ax)));
  return x < 0 ? std::numbers::pi - r : r;
}

}  // namespace detail

template <typename Visit>
void HemisphereDirections::for_each_in_cap(const Eigen::Vector3d& axis, double cos_half_angle,
                                           Visit&& visit) const {
  const double zc = axis.z();
  const double sc = std::sqrt(std::max(0.0, 1.0 - zc * zc));
  const double sin_half = std::sqrt(std::max(0.0, 1.0 - cos_half_angle * cos_half_angle));
  // z range of directions inside the cap: cos(theta_c +- alpha), widened a little so rounding
  // never drops a ring; the exact test below decides.
  // The cap reaches the zenith when theta_c < alpha (zc > cos alpha), the nadir when
  // pi - theta_c < alpha (-zc > cos alpha).
  const double z_lo = -zc > cos_half_angle ? -1.0 : zc * cos_half_angle - sc * sin_half - 1e-9;
  const double z_hi = zc > cos_half_angle ? 1.0 : zc * cos_half_angle + sc * sin_half + 1e-9;
  if (z_hi <= 0.0) return;
  const double phi_c = detail::fast_atan2(axis.y(), axis.x());
  const int rings = ring_count();
  for (int r = 0; r < rings; ++r) {
    const double z = ring_z_[r];
    if (z > z_hi) continue;
    if (z < z_lo) break;  // rings are ordered by decreasing z
    const int n = ring_size_[r];
    const int first = ring_first_[r];
    const double s = std::sqrt(1.0 - z * z);
    const double denom = s * sc;
    int k0 = 0, k1 = n - 1;
    if (denom > 1e-12) {
      const double c = (cos_half_angle - z * zc) / denom;
      if (c > 1.0 + 1e-9) continue;
      if (c > -1.0) {
        const double half = detail::fast_acos(std::min(1.0, c));
        const double step = 2.0 * std::numbers::pi / n;
        const double u = (phi_c - ring_offset_[r]) / step - 0.5;
        const double w = half / step;
        const int lo = static_cast<int>(std::floor(u - w)) - 1;  // >= -n
        const int hi = static_cast<int>(std::ceil(u + w)) + 1;
        if (hi - lo + 1 < n) {
          for (int k = lo; k <= hi; ++k) {
            const int i = first + (k < 0 ? k + n : (k >= n ? k - n : k));
            if (dirs_[i].dot(axis) >= cos_half_angle) visit(i);
          }
          continue;
        }
      }
    }
    for (int k = k0; k <= k1; ++k) {
      const int i = first + k;
      if (dirs_[i].dot(axis) >= cos_half_angle) visit(i);
    }
  }
}

}  // namespace fspm::environment
