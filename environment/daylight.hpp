#pragma once
// Absolute light at points under a real sky: the sun at a site, date and hours, its clear-sky or
// given global radiation split into the sun's beam and the diffuse sky (sky_radiation.hpp), and
// both taken through the crown and the obstacles (CanopyLight): photosynthetically active photon
// flux density on a horizontal plane at each point, as a horizontal quantum sensor reads it, and
// its integral over the hours.
//
//   E(p, t) = S_b(t) T(p, s(t)) + S_d(t) sum_i L(d_i) cos(theta_i) T(p, d_i) / sum_i L(d_i)
//   cos(theta_i)
//
// S_b, S_d: direct and diffuse irradiance on a horizontal plane; s(t): the sun's direction;
// T(p, d): transmission along d; L: the diffuse sky's radiance (CIE standard overcast or clear);
// the d_i are the sky's equal-area directions. An unobstructed point receives S_b + S_d = S_g.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/sky_radiation.hpp"
#include "environment/solar_position.hpp"

namespace fspm::environment {

struct RealSky {
  Site site;
  CalendarDate date;
  double first_hour = 0.0;  // local clock time
  double last_hour = 24.0;
  double step_h = 0.25;  // integration step (midpoint rule)
  DiffuseSky diffuse = DiffuseSky::kStandardOvercast;
  DiffuseSplit split = DiffuseSplit::kSpitters;  // of the global radiation into direct and diffuse
  double transmittance = 0.75;  // clear-sky atmospheric transmittance (Campbell and Norman)
  // Global radiation on a horizontal plane (W m-2) held over the hours while the sun is up,
  // split by Spitters et al. (1986); negative: the clear sky of the site and date.
  double global_W_m2 = -1.0;
  // Measured hourly global radiation (W m-2, index = local hour 0-23, radiation_file.hpp); when
  // given it replaces global_W_m2 and the clear sky, each step taking its hour's value.
  std::vector<double> hourly_global_W_m2;
  // Throws ValueError naming the field for hours outside [0, 24], first > last, a step <= 0, a
  // transmittance outside (0, 1] or an invalid site or date.
  void validate() const;
};

// "YYYY-MM-DD"; "FROM:TO" hours (local clock time, e.g. "6:18" or "5.5:20.25") into sky; a
// diffuse sky's name ("overcast", "clear", "uniform"). Each throws ValueError saying what was
// expected.
CalendarDate parse_date(std::string_view text);
void parse_hours(std::string_view text, RealSky& sky);
DiffuseSky diffuse_sky_from_name(std::string_view name);

// One integration step: the sun and the radiation on a horizontal plane in the open.
struct SkyStep {
  double hour = 0.0;  // local time of the step's middle
  Eigen::Vector3d sun = Eigen::Vector3d::UnitZ();
  double sun_elevation_deg = 0.0;
  HorizontalRadiation radiation;
};
std::vector<SkyStep> sky_steps(const RealSky& sky);

struct DaylightSample {
  double par_umol_m2_s = 0.0;     // mean over the hours (night included)
  double daily_par_mol_m2 = 0.0;  // integral over the hours
  double open_fraction = 0.0;     // daily PAR against that of an unobstructed point
};

// PAR at each point (leaving out cluster ignore[k] at point k when `ignore` is not empty).
std::vector<DaylightSample> daylight_at(const CanopyLight& light, const RealSky& sky,
                                        std::span<const Eigen::Vector3d> points,
                                        std::span<const std::uint32_t> ignore = {});

// The same through the clusters as turbid media in voxels (CanopySweep of voxel_m, the leaf light
// model "sweep"): one sweep per diffuse sky direction (scene.sky.directions) and one per step with
// the sun up, whatever the number of points; the scene's boxes, meshes, spheres and ground by their
// translucency along each ray. Each point's own cluster shades it (the light of its leaves).
std::vector<DaylightSample> daylight_through_voxels(std::span<const Sphere> clusters,
                                                    const Scene& scene, const RealSky& sky,
                                                    std::span<const Eigen::Vector3d> points,
                                                    double voxel_m);

}  // namespace fspm::environment
