#include "environment/sky_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <tuple>

#include "environment/canopy_sweep.hpp"
#include "environment/leaf_light_model.hpp"

namespace fspm::environment {
namespace {

// Sun positions of several days closer than about 2 degrees share a bin (cubes of 0.035 of the
// unit vector's components).
constexpr double kSunBin = 0.035;

bool leap(int year) { return (year % 4 == 0 && year % 100 != 0) || year % 400 == 0; }

CalendarDate next_day(CalendarDate d) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const int length = kDays[d.month - 1] + (d.month == 2 && leap(d.year) ? 1 : 0);
  if (++d.day > length) {
    d.day = 1;
    if (++d.month > 12) d.month = 1, ++d.year;
  }
  return d;
}

// Adds one day's steps; with `merge`, a step joins the bin of its sun position.
void add_day(const RealSky& sky, bool merge, std::map<std::tuple<int, int, int>, std::size_t>& bins,
             SkyDistribution& out) {
  const std::vector<SkyStep> steps = sky_steps(sky);
  const double dt_s = 3600.0 * (sky.last_hour - sky.first_hour) / static_cast<double>(steps.size());
  out.seconds += dt_s * static_cast<double>(steps.size());
  for (const SkyStep& s : steps) {
    const double direct = par_umol_m2_s(s.radiation.direct_W_m2) * dt_s * 1e-6;
    const double diffuse = par_umol_m2_s(s.radiation.diffuse_W_m2) * dt_s * 1e-6;
    if (direct <= 0.0 && diffuse <= 0.0) continue;
    // A sun on or below the horizon lends only its diffuse sky (its direction is kept for the
    // CIE clear sky's radiance); its beam is zero.
    std::size_t at = out.suns.size();
    if (merge) {
      const auto key = std::make_tuple(static_cast<int>(std::floor(s.sun.x() / kSunBin)),
                                       static_cast<int>(std::floor(s.sun.y() / kSunBin)),
                                       static_cast<int>(std::floor(s.sun.z() / kSunBin)));
      const auto [it, fresh] = bins.emplace(key, out.suns.size());
      at = it->second;
      if (!fresh) {
        // The bin's direction: the mean of its positions weighted by their light.
        const double w0 = out.direct_mol_m2[at] + out.diffuse_mol_m2[at];
        const double w = direct + diffuse;
        out.suns[at] = (w0 * out.suns[at] + w * s.sun).normalized();
        out.direct_mol_m2[at] += direct;
        out.diffuse_mol_m2[at] += diffuse;
        continue;
      }
    }
    out.suns.push_back(s.sun);
    out.direct_mol_m2.push_back(direct);
    out.diffuse_mol_m2.push_back(diffuse);
  }
}

// Diffuse weights L(d_i) cos(theta_i) over dirs, normalised to sum 1.
std::vector<double> diffuse_shares(const HemisphereDirections& dirs, DiffuseSky sky,
                                   const Eigen::Vector3d& sun) {
  std::vector<double> w(static_cast<std::size_t>(dirs.size()));
  double sum = 0.0;
  for (int i = 0; i < dirs.size(); ++i) {
    const Eigen::Vector3d& d = dirs.direction(i);
    w[static_cast<std::size_t>(i)] = sky_radiance(sky, d, sun) * d.z();
    sum += w[static_cast<std::size_t>(i)];
  }
  for (double& v : w) v = sum > 0.0 ? v / sum : 0.0;
  return w;
}

// The cell of dirs holding unit direction d (z > 0): its ring by z (a ring of n cells spans n/N
// in z), then its cell by azimuth.
int cell_holding(const HemisphereDirections& dirs, const Eigen::Vector3d& d) {
  const double n = static_cast<double>(dirs.size());
  double z_top = 1.0;
  int ring = dirs.ring_count() - 1;
  for (int r = 0; r < dirs.ring_count(); ++r) {
    z_top -= dirs.ring_size(r) / n;
    if (d.z() >= z_top) {
      ring = r;
      break;
    }
  }
  const int size = dirs.ring_size(ring);
  const double step = 2.0 * std::numbers::pi / size;
  double phi = std::atan2(d.y(), d.x()) - dirs.ring_offset(ring);
  phi -= 2.0 * std::numbers::pi * std::floor(phi / (2.0 * std::numbers::pi));
  return dirs.ring_first(ring) + std::min(size - 1, static_cast<int>(phi / step));
}

}  // namespace

double SkyDistribution::open_direct_mol_m2() const {
  double s = 0.0;
  for (double v : direct_mol_m2) s += v;
  return s;
}

double SkyDistribution::open_diffuse_mol_m2() const {
  double s = 0.0;
  for (double v : diffuse_mol_m2) s += v;
  return s;
}

std::vector<double> SkyDistribution::cell_mol_m2(const HemisphereDirections& dirs) const {
  std::vector<double> w(static_cast<std::size_t>(dirs.size()), 0.0);
  // The overcast and uniform skies do not depend on the sun: one set of shares for all steps.
  const bool follows_sun = diffuse == DiffuseSky::kClear;
  std::vector<double> shares;
  if (!follows_sun) shares = diffuse_shares(dirs, diffuse, Eigen::Vector3d::UnitZ());
  double still = 0.0;  // diffuse light of the skies that do not follow the sun
  for (std::size_t k = 0; k < suns.size(); ++k) {
    if (direct_mol_m2[k] > 0.0 && suns[k].z() > 0.0) {
      w[static_cast<std::size_t>(cell_holding(dirs, suns[k]))] += direct_mol_m2[k];
    }
    if (diffuse_mol_m2[k] <= 0.0) continue;
    if (!follows_sun) {
      still += diffuse_mol_m2[k];
      continue;
    }
    const std::vector<double> s = diffuse_shares(dirs, diffuse, suns[k]);
    for (std::size_t i = 0; i < w.size(); ++i) w[i] += diffuse_mol_m2[k] * s[i];
  }
  for (std::size_t i = 0; i < shares.size(); ++i) w[i] += still * shares[i];
  return w;
}

Eigen::Vector3d SkyDistribution::mean_direction() const {
  const HemisphereDirections dirs(256);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < suns.size(); ++k) {
    if (suns[k].z() > 0.0) total += direct_mol_m2[k] * suns[k];
    if (diffuse_mol_m2[k] <= 0.0) continue;
    const std::vector<double> s = diffuse_shares(dirs, diffuse, suns[k]);
    for (int i = 0; i < dirs.size(); ++i) {
      total += diffuse_mol_m2[k] * s[static_cast<std::size_t>(i)] * dirs.direction(i);
    }
  }
  return total.z() > 0.0 ? Eigen::Vector3d(total.normalized()) : Eigen::Vector3d::UnitZ();
}

SkyDistribution sky_distribution(const RealSky& sky) {
  SkyDistribution out;
  out.diffuse = sky.diffuse;
  std::map<std::tuple<int, int, int>, std::size_t> bins;
  add_day(sky, false, bins, out);
  return out;
}

SkyDistribution sky_distribution(const SiteSky& site_sky) {
  if (site_sky.days <= 0) return sky_distribution(site_sky.sky);
  SkyDistribution out;
  out.diffuse = site_sky.sky.diffuse;
  RealSky sky = site_sky.sky;
  sky.first_hour = 0.0, sky.last_hour = 24.0;
  std::map<std::tuple<int, int, int>, std::size_t> bins;
  for (int d = 0; d < site_sky.days; ++d) {
    add_day(sky, site_sky.days > 1, bins, out);
    out.days = site_sky.days;
    sky.date = next_day(sky.date);
  }
  return out;
}

void apply_sky_distribution(Sky& sky, std::shared_ptr<const SkyDistribution> shared) {
  const SkyDistribution& distribution = *shared;
  sky.brightest = distribution.mean_direction();
  sky.analytic = false;  // the closed forms integrate the cos^2 sky
  sky.analytic_boxes = false;
  const HemisphereDirections dirs(sky.directions);
  const std::vector<double> w = distribution.cell_mol_m2(dirs);
  double sum = 0.0, peak = 0.0;
  for (double v : w) sum += v, peak = std::max(peak, v);
  if (sum > 0.0) {
    const double ratio = static_cast<double>(dirs.size()) * peak / sum;  // 3 for cos^2
    sky.significance *= std::min(1.0, 3.0 / ratio);
  }
  sky.distribution = std::move(shared);
}

std::vector<double> sky_weights(const Sky& sky, const HemisphereDirections& dirs) {
  std::vector<double> w(static_cast<std::size_t>(dirs.size()));
  if (sky.distribution) {
    w = sky.distribution->cell_mol_m2(dirs);
    double sum = 0.0;
    for (double v : w) sum += v;
    if (sum > 0.0) return w;
    // A sky without light (night only): every direction alike, nothing is lit anyway.
    std::fill(w.begin(), w.end(), 1.0);
    return w;
  }
  const Eigen::Vector3d b = sky.brightest.norm() > 0.0 ? Eigen::Vector3d(sky.brightest.normalized())
                                                       : Eigen::Vector3d::UnitZ();
  for (int i = 0; i < dirs.size(); ++i) {
    const double c = dirs.direction(i).dot(b);
    w[static_cast<std::size_t>(i)] = c * c;  // Pirk eq. 4.3: I = cos^2(angle to the brightest)
  }
  return w;
}

std::vector<DaylightSample> daylight_through_voxels(std::span<const Sphere> clusters,
                                                    const Scene& scene, const SkyDistribution& sky,
                                                    std::span<const Eigen::Vector3d> points,
                                                    double voxel_m) {
  const std::size_t np = points.size();
  std::vector<double> mol(np, 0.0);
  CanopySweep sweep(scene.sky.directions, Eigen::Vector3d::UnitZ(), voxel_m);
  const HemisphereDirections& dirs = sweep.directions();
  std::vector<std::vector<float>> vis(np);
  for (std::size_t k = 0; k < np; ++k) vis[k] = obstacle_visibility(scene, dirs, points[k]);
  // Diffuse light: every point's transmission per sky direction (one sweep each) weighted by the
  // diffuse PAR per direction (the distribution without its suns' beams).
  SkyDistribution diffuse_only = sky;
  std::fill(diffuse_only.direct_mol_m2.begin(), diffuse_only.direct_mol_m2.end(), 0.0);
  const std::vector<double> w = diffuse_only.cell_mol_m2(dirs);
  if (diffuse_only.open_diffuse_mol_m2() > 0.0) {
    std::vector<Eigen::Vector3d> sky_dirs(w.size());
    for (int i = 0; i < dirs.size(); ++i) sky_dirs[static_cast<std::size_t>(i)] = dirs.direction(i);
    std::vector<float> t(sky_dirs.size() * np);
    sweep.transmissions(clusters, points, sky_dirs, t);
    for (std::size_t i = 0; i < w.size(); ++i) {
      const float* ti = t.data() + i * np;
      for (std::size_t k = 0; k < np; ++k) {
        mol[k] += w[i] * ti[k] * (vis[k].empty() ? 1.0f : vis[k][i]);
      }
    }
  }
  // The sun's beam: one sweep per position with the sun up.
  std::vector<Eigen::Vector3d> suns;
  std::vector<double> direct;
  for (std::size_t j = 0; j < sky.suns.size(); ++j) {
    if (sky.direct_mol_m2[j] <= 0.0 || sky.suns[j].z() <= 0.0) continue;
    suns.push_back(sky.suns[j]);
    direct.push_back(sky.direct_mol_m2[j]);
  }
  std::vector<float> beam(suns.size() * np);
  if (!suns.empty()) sweep.transmissions(clusters, points, suns, beam);
  const bool obstacles = !scene.spheres.empty() || !scene.boxes.empty() || !scene.meshes.empty() ||
                         scene.ground.has_value();
  for (std::size_t j = 0; j < suns.size(); ++j) {
    for (std::size_t k = 0; k < np; ++k) {
      const double o = obstacles ? obstacle_transmission(scene, points[k], suns[j]) : 1.0;
      mol[k] += direct[j] * beam[j * np + k] * o;
    }
  }
  const double open = sky.open_mol_m2();
  std::vector<DaylightSample> out(np);
  for (std::size_t k = 0; k < np; ++k) {
    out[k].daily_par_mol_m2 = mol[k] / std::max(sky.days, 1);
    out[k].par_umol_m2_s = sky.seconds > 0.0 ? mol[k] * 1e6 / sky.seconds : 0.0;
    out[k].open_fraction = open > 0.0 ? mol[k] / open : 0.0;
  }
  return out;
}

}  // namespace fspm::environment
