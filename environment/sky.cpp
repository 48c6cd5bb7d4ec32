#include "environment/sky.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"
#include "fspm/scene_description.hpp"

namespace fspm::environment {
namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
}

void Sky::validate() const {
  const Sky& sky = *this;
  if (!sky.brightest.allFinite() || std::abs(sky.brightest.norm() - 1.0) > 1e-9) {
    throw ValueError(
        "sky brightest: expected a non-zero direction (a unit vector once normalized)");
  }
  if (sky.directions < 1 || sky.directions > kMaxSkyDirections) {
    throw ValueError("sky directions: expected a count in [1, " +
                     std::to_string(kMaxSkyDirections) + "], got " +
                     std::to_string(sky.directions));
  }
  if (!(sky.significance >= 0.0 && sky.significance < 1.0)) {
    throw ValueError("sky significance: expected a number in [0, 1), got " +
                     std::to_string(sky.significance));
  }
}

Eigen::Vector3d direction_from_elevation_azimuth(double elevation_deg, double azimuth_deg) {
  const double e = elevation_deg * kDegToRad;
  const double a = azimuth_deg * kDegToRad;
  return {std::cos(e) * std::sin(a), std::cos(e) * std::cos(a), std::sin(e)};
}

double solar_declination_deg(int day_of_year) {
  return 23.45 * std::sin(2.0 * std::numbers::pi / 365.0 * (284.0 + day_of_year));
}

Eigen::Vector3d noon_sun_direction(double latitude_deg, int day_of_year) {
  const double decl = solar_declination_deg(day_of_year);
  const double elevation = 90.0 - std::abs(latitude_deg - decl);
  const double azimuth = latitude_deg >= decl ? 180.0 : 0.0;
  return direction_from_elevation_azimuth(elevation, azimuth);
}

}  // namespace fspm::environment
