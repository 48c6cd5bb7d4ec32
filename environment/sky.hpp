#pragma once
// The sky of Pirk eq. 4.3: intensity I = cos^2(angle to the brightest point), z up, x east, y
// north.
#include <Eigen/Core>
#include <memory>
#include <vector>

namespace fspm::environment {

struct SkyDistribution;  // sky_distribution.hpp
class HemisphereDirections;

struct Sky {
  Eigen::Vector3d brightest = Eigen::Vector3d::UnitZ();  // unit vector to the brightest sky point
  int directions = 256;        // stratified sample directions over the upper hemisphere
  double significance = 1e-3;  // shadow-volume cutoff: max ignored share of light per occluder
  bool analytic = true;        // exact sphere-cap integrals where they are exact (see light_model)
  // With analytic: boxes and walls in closed form (spherical polygons, see light_model). Off, they
  // are ray-cast over the directions like meshes.
  bool analytic_boxes = true;
  // A real sky's light per direction (sky_distribution.hpp, apply_sky_distribution) in place of
  // the cos^2 sky; null: the cos^2 sky around `brightest`.
  std::shared_ptr<const SkyDistribution> distribution;
  // Throws ValueError naming the field unless brightest is a finite unit vector, directions is in
  // [1, kMaxSkyDirections] and significance in [0, 1). (A brightest point below the horizon is
  // allowed: the cos^2 sky of -b is the same as that of b.)
  void validate() const;
};

// The sky's intensity per cell of dirs, in any unit (only ratios matter): cos^2 of the angle to
// the brightest point (Pirk eq. 4.3), or the real sky's PAR per cell (SkyDistribution).
std::vector<double> sky_weights(const Sky& sky, const HemisphereDirections& dirs);

// Unit direction from elevation above the horizon and azimuth clockwise from north (degrees).
Eigen::Vector3d direction_from_elevation_azimuth(double elevation_deg, double azimuth_deg);

// Solar declination (Cooper 1969): 23.45 deg * sin(360/365 * (284 + day)).
double solar_declination_deg(int day_of_year);

// The sun at solar noon for a latitude (north positive) and day of year (1..366): elevation
// 90 - |latitude - declination|, due south when the sun culminates south of the zenith, else north.
Eigen::Vector3d noon_sun_direction(double latitude_deg, int day_of_year);

}  // namespace fspm::environment
