#include "environment/sky_radiation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"

namespace fspm::environment {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

double extraterrestrial_horizontal_W_m2(double sun_elevation_deg, int day_of_year) {
  const double sin_beta = std::sin(sun_elevation_deg * kDeg);
  if (sin_beta <= 0.0) return 0.0;
  return kSolarConstant_W_m2 *
         (1.0 + 0.033 * std::cos(2.0 * std::numbers::pi * day_of_year / 365.0)) * sin_beta;
}

double clear_sky_global_W_m2(double sun_elevation_deg, int day_of_year, double elevation_m,
                             double transmittance) {
  const double cos_z = std::sin(sun_elevation_deg * kDeg);
  if (cos_z <= 0.0) return 0.0;
  const double pa_kpa = 101.3 * std::exp(-elevation_m / 8200.0);
  const double m = pa_kpa / (101.3 * cos_z);
  const double tm = std::pow(transmittance, m);
  const double s0 = extraterrestrial_horizontal_W_m2(sun_elevation_deg, day_of_year);
  return s0 * tm + 0.3 * (1.0 - tm) * s0;
}

double spitters_diffuse_fraction(double global_W_m2, double sun_elevation_deg, int day_of_year) {
  const double s0 = extraterrestrial_horizontal_W_m2(sun_elevation_deg, day_of_year);
  if (s0 <= 0.0 || global_W_m2 <= 0.0) return 1.0;
  const double t = global_W_m2 / s0;
  const double sin_beta = std::sin(sun_elevation_deg * kDeg);
  const double r = 0.847 - 1.61 * sin_beta + 1.04 * sin_beta * sin_beta;
  const double k = (1.47 - r) / 1.66;
  if (t <= 0.22) return 1.0;
  if (t <= 0.35) return 1.0 - 6.4 * (t - 0.22) * (t - 0.22);
  if (t <= k) return 1.47 - 1.66 * t;
  return r;
}

double erbs_diffuse_fraction(double global_W_m2, double sun_elevation_deg, int day_of_year) {
  const double s0 = extraterrestrial_horizontal_W_m2(sun_elevation_deg, day_of_year);
  if (s0 <= 0.0 || global_W_m2 <= 0.0) return 1.0;
  const double kt = global_W_m2 / s0;
  if (kt <= 0.22) return 1.0 - 0.09 * kt;
  if (kt <= 0.80) {
    return 0.9511 - 0.1604 * kt + 4.388 * kt * kt - 16.638 * kt * kt * kt +
           12.336 * kt * kt * kt * kt;
  }
  return 0.165;
}

DiffuseSplit diffuse_split_from_name(std::string_view name) {
  return kDiffuseSplitNames.from_name(name);
}

HorizontalRadiation split_global(double global_W_m2, double sun_elevation_deg, int day_of_year,
                                 DiffuseSplit split) {
  const double raw = split == DiffuseSplit::kErbs
                         ? erbs_diffuse_fraction(global_W_m2, sun_elevation_deg, day_of_year)
                         : spitters_diffuse_fraction(global_W_m2, sun_elevation_deg, day_of_year);
  const double f = std::clamp(raw, 0.0, 1.0);
  HorizontalRadiation out;
  out.diffuse_W_m2 = f * global_W_m2;
  out.direct_W_m2 = global_W_m2 - out.diffuse_W_m2;
  return out;
}

double sky_radiance(DiffuseSky sky, const Eigen::Vector3d& d, const Eigen::Vector3d& sun) {
  const double cos_theta = std::max(d.z(), 0.0);
  switch (sky) {
    case DiffuseSky::kStandardOvercast:
      return (1.0 + 2.0 * cos_theta) / 3.0;
    case DiffuseSky::kUniform:
      return 1.0;
    case DiffuseSky::kClear: {
      // CIE S 011/E:2003 type 12: L = phi(Z) f(chi), phi(Z) = 1 + a exp(b / cos Z),
      // f(chi) = 1 + c (exp(d chi) - exp(d pi / 2)) + e cos^2 chi.
      constexpr double a = -1.0, b = -0.32, c = 10.0, dd = -3.0, e = 0.45;
      const double phi = 1.0 + a * std::exp(b / std::max(cos_theta, 1e-6));
      const double chi = std::acos(std::clamp(d.dot(sun), -1.0, 1.0));
      const double f = 1.0 + c * (std::exp(dd * chi) - std::exp(dd * std::numbers::pi / 2.0)) +
                       e * std::cos(chi) * std::cos(chi);
      return std::max(phi * f, 0.0);
    }
  }
  return 1.0;
}

}  // namespace fspm::environment
