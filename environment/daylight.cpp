#include "environment/daylight.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

#include "environment/canopy_sweep.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/sky_distribution.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

namespace {

double parse_number(std::string_view text, const char* what) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v)) {
    throw ValueError(std::string("expected ") + what + ", got \"" + std::string(text) + "\"");
  }
  return v;
}

}  // namespace

CalendarDate parse_date(std::string_view text) {
  const auto bad = [&] {
    return ValueError("expected a date YYYY-MM-DD, got \"" + std::string(text) + "\"");
  };
  if (text.size() != 10 || text[4] != '-' || text[7] != '-') throw bad();
  CalendarDate d;
  const auto field = [&](std::size_t at, std::size_t n, int& out) {
    const auto [end, ec] = std::from_chars(text.data() + at, text.data() + at + n, out);
    if (ec != std::errc() || end != text.data() + at + n) throw bad();
  };
  field(0, 4, d.year);
  field(5, 2, d.month);
  field(8, 2, d.day);
  return d;
}

void parse_hours(std::string_view text, RealSky& sky) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) {
    throw ValueError("expected hours FROM:TO (local time, e.g. 6:18), got \"" + std::string(text) +
                     "\"");
  }
  sky.first_hour = parse_number(text.substr(0, colon), "the first hour (0-24)");
  sky.last_hour = parse_number(text.substr(colon + 1), "the last hour (0-24)");
}

DiffuseSky diffuse_sky_from_name(std::string_view name) { return kDiffuseSkyNames.from_name(name); }

void RealSky::validate() const {
  const RealSky& sky = *this;
  if (!(sky.first_hour >= 0.0 && sky.last_hour <= 24.0 && sky.first_hour < sky.last_hour)) {
    throw ValueError("sky hours must satisfy 0 <= first < last <= 24, got " +
                     std::to_string(sky.first_hour) + " to " + std::to_string(sky.last_hour));
  }
  if (!(sky.step_h > 0.0)) throw ValueError("sky time step must be > 0 hours");
  if (!(sky.transmittance > 0.0 && sky.transmittance <= 1.0)) {
    throw ValueError("sky transmittance must be in (0, 1], got " +
                     std::to_string(sky.transmittance));
  }
  if (!std::isfinite(sky.global_W_m2)) throw ValueError("global radiation must be finite");
  if (!sky.hourly_global_W_m2.empty() && sky.hourly_global_W_m2.size() != 24) {
    throw ValueError("hourly global radiation needs 24 values (hours 0-23), got " +
                     std::to_string(sky.hourly_global_W_m2.size()));
  }
  sky.site.validate();
  sky.date.validate();
}

std::vector<SkyStep> sky_steps(const RealSky& sky) {
  sky.validate();
  const int doy = day_of_year(sky.date);
  const int n = std::max(
      1, static_cast<int>(std::ceil((sky.last_hour - sky.first_hour) / sky.step_h - 1e-9)));
  const double dt = (sky.last_hour - sky.first_hour) / n;
  std::vector<SkyStep> steps;
  for (int k = 0; k < n; ++k) {
    SkyStep s;
    s.hour = sky.first_hour + (k + 0.5) * dt;
    const SolarPosition sun = solar_position(sky.site, sky.date, s.hour);
    s.sun = sun.direction();
    s.sun_elevation_deg = sun.elevation_deg();
    if (s.sun_elevation_deg > 0.0) {
      double global = 0.0;
      if (!sky.hourly_global_W_m2.empty()) {
        global = sky.hourly_global_W_m2[std::clamp(static_cast<int>(std::floor(s.hour)), 0, 23)];
      } else if (sky.global_W_m2 >= 0.0) {
        global = sky.global_W_m2;
      } else {
        global = clear_sky_global_W_m2(s.sun_elevation_deg, doy, sky.site.elevation_m,
                                       sky.transmittance);
      }
      s.radiation = split_global(global, s.sun_elevation_deg, doy, sky.split);
    }
    steps.push_back(s);
  }
  return steps;
}

namespace {

// Diffuse weights L(d_i) cos(theta_i), normalised to sum 1.
std::vector<double> diffuse_weights(const HemisphereDirections& dirs, DiffuseSky sky,
                                    const Eigen::Vector3d& sun) {
  std::vector<double> w(dirs.size());
  double sum = 0.0;
  for (int i = 0; i < dirs.size(); ++i) {
    const Eigen::Vector3d& d = dirs.direction(i);
    w[i] = sky_radiance(sky, d, sun) * d.z();
    sum += w[i];
  }
  for (double& v : w) v = sum > 0.0 ? v / sum : 0.0;
  return w;
}

}  // namespace

std::vector<DaylightSample> daylight_at(const CanopyLight& light, const RealSky& sky,
                                        std::span<const Eigen::Vector3d> points,
                                        std::span<const std::uint32_t> ignore) {
  const std::vector<SkyStep> steps = sky_steps(sky);
  const double dt_s = 3600.0 * (sky.last_hour - sky.first_hour) / steps.size();
  double open_mol = 0.0;
  for (const SkyStep& s : steps) open_mol += par_umol_m2_s(s.radiation.global_W_m2()) * dt_s * 1e-6;
  std::vector<double> mol(points.size(), 0.0);
  // Diffuse light: each point's transmission per direction once, then every step's sky weights.
  std::vector<std::vector<double>> weights;
  std::vector<double> diffuse_w_m2;
  for (const SkyStep& s : steps) {
    if (s.radiation.diffuse_W_m2 <= 0.0) continue;
    weights.push_back(diffuse_weights(light.directions(), sky.diffuse, s.sun));
    diffuse_w_m2.push_back(s.radiation.diffuse_W_m2);
  }
  std::vector<double> t;
  for (std::size_t k = 0; k < points.size() && !weights.empty(); ++k) {
    light.transmission(points[k], ignore.empty() ? kNoSphere : ignore[k], t);
    for (std::size_t j = 0; j < weights.size(); ++j) {
      double diffuse = 0.0;
      for (std::size_t i = 0; i < t.size(); ++i) diffuse += weights[j][i] * t[i];
      mol[k] += par_umol_m2_s(diffuse_w_m2[j] * diffuse) * dt_s * 1e-6;
    }
  }
  // The sun's beam: every point at once per step.
  std::vector<double> beam(points.size());
  for (const SkyStep& s : steps) {
    if (s.radiation.direct_W_m2 <= 0.0) continue;
    light.transmission_along(points, s.sun, ignore, beam);
    for (std::size_t k = 0; k < points.size(); ++k) {
      mol[k] += par_umol_m2_s(s.radiation.direct_W_m2 * beam[k]) * dt_s * 1e-6;
    }
  }
  std::vector<DaylightSample> out(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    out[k].daily_par_mol_m2 = mol[k];
    out[k].par_umol_m2_s = mol[k] * 1e6 / (dt_s * steps.size());
    out[k].open_fraction = open_mol > 0.0 ? mol[k] / open_mol : 0.0;
  }
  return out;
}

std::vector<DaylightSample> daylight_through_voxels(std::span<const Sphere> clusters,
                                                    const Scene& scene, const RealSky& sky,
                                                    std::span<const Eigen::Vector3d> points,
                                                    double voxel_m) {
  return daylight_through_voxels(clusters, scene, sky_distribution(sky), points, voxel_m);
}

}  // namespace fspm::environment
