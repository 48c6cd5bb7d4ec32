// Wind sway of a tree skeleton as per-joint rotation keyframes.
#include "graphics/wind_animation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

constexpr double kTwoPi = 6.283185307179586;

}  // namespace

Eigen::Vector3f sway_axis(const WindOptions& options) {
  Eigen::Vector3d wind = options.direction;
  wind.z() = 0.0;
  return Eigen::Vector3d::UnitZ().cross(wind.normalized()).cast<float>();
}

std::vector<Eigen::Quaternionf> wind_pose(const Skeleton& skeleton, const WindOptions& options,
                                          double t_s) {
  options.validate();
  std::mt19937_64 rng(options.seed);
  const std::vector<JointSway> sways = joint_sways(skeleton, options, rng);
  const Eigen::Vector3f axis = sway_axis(options);
  std::vector<Eigen::Quaternionf> out;
  out.reserve(sways.size());
  for (const JointSway& sway : sways) out.push_back(sway_rotation(sway, axis, t_s, options));
  return out;
}

void WindOptions::validate() const {
  const Eigen::Vector2d horizontal = direction.head<2>();
  if (!direction.allFinite() || horizontal.norm() < 1e-9) {
    throw ValueError("wind: direction needs a horizontal component");
  }
  if (!(amplitude_rad >= 0.0) || !std::isfinite(amplitude_rad)) {
    throw ValueError("wind: amplitude_rad must be a finite angle >= 0");
  }
  if (!(duration_s > 0.0 && frames_per_second > 0.0 && frequency_hz > 0.0) ||
      !std::isfinite(duration_s * frames_per_second * frequency_hz)) {
    throw ValueError("wind: duration_s, frames_per_second and frequency_hz must be positive");
  }
  if (duration_s * frames_per_second > 1e6) {
    throw ValueError(
        "wind: more than a million keyframes: shorten duration_s or frames_per_second");
  }
  if (!(bias >= 0.0 && bias <= 1.0)) throw ValueError("wind: bias must lie in [0, 1]");
}

double looping_frequency_hz(const WindOptions& o) {
  return std::max(1.0, std::round(o.frequency_hz * o.duration_s)) / o.duration_s;
}

std::vector<JointSway> joint_sways(const Skeleton& s, const WindOptions& o, std::mt19937_64& rng) {
  std::vector<JointSway> out(s.size());
  if (s.size() == 0) return out;
  const double min_radius =
      std::max(1e-6, static_cast<double>(*std::min_element(s.radii_m.begin(), s.radii_m.end())));
  const double mean_length =
      std::accumulate(s.lengths_m.begin(), s.lengths_m.end(), 0.0) / static_cast<double>(s.size());
  std::uniform_real_distribution<double> phase(0.0, kTwoPi);
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double r = std::max(min_radius, static_cast<double>(s.radii_m[j]));
    const double l = mean_length > 0.0 ? s.lengths_m[j] / mean_length : 1.0;
    out[j].amplitude_rad = o.amplitude_rad * std::pow(min_radius / r, o.stiffness_exponent) * l;
    // A joint continuing its parent's axis (same order) keeps the parent's phases.
    const int p = s.parents[j];
    if (p >= 0 && s.orders[p] == s.orders[j]) {
      out[j].phase_rad = out[p].phase_rad;
      out[j].overtone_phase_rad = out[p].overtone_phase_rad;
    } else {
      out[j].phase_rad = phase(rng);
      out[j].overtone_phase_rad = phase(rng);
    }
  }
  return out;
}

Eigen::Quaternionf sway_rotation(const JointSway& sway, const Eigen::Vector3f& axis, double t_s,
                                 const WindOptions& o) {
  const double w = kTwoPi * looping_frequency_hz(o);
  const double swing = 0.75 * std::sin(w * t_s + sway.phase_rad) +
                       0.25 * std::sin(2.0 * w * t_s + sway.overtone_phase_rad);
  const double angle = sway.amplitude_rad * (o.bias + (1.0 - o.bias) * swing);
  return Eigen::Quaternionf(Eigen::AngleAxisf(static_cast<float>(angle), axis));
}

WindAnimation wind_animation(const Skeleton& skeleton, const WindOptions& o) {
  o.validate();
  std::mt19937_64 rng(o.seed);
  const std::vector<JointSway> sways = joint_sways(skeleton, o, rng);
  WindAnimation a;
  a.axis = sway_axis(o);
  const auto n = static_cast<std::size_t>(std::ceil(o.duration_s * o.frames_per_second - 1e-9));
  for (std::size_t k = 0; k <= n; ++k) {
    const double t = std::min(o.duration_s, static_cast<double>(k) / o.frames_per_second);
    a.times_s.push_back(static_cast<float>(t));
    std::vector<Eigen::Quaternionf> frame(skeleton.size());
    for (std::size_t j = 0; j < skeleton.size(); ++j) {
      frame[j] = sway_rotation(sways[j], a.axis, t, o);
    }
    a.frames.push_back(std::move(frame));
  }
  return a;
}

}  // namespace fspm::graphics
