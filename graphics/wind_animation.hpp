#pragma once
// Trees swaying in the wind as joint rotations of a skeleton (graphics/skeleton_skin.hpp), the
// keyframes a glTF animation plays. Each joint bends about the horizontal axis across the wind,
// up x wind, by
//   angle(t) = A_j (bias + (1 - bias) (0.75 sin(w t + phi) + 0.25 sin(2 w t + psi)))
// a lean with the wind plus a sway and its first overtone. Bending stiffness of a round branch
// grows with its radius (second moment of area pi r^4 / 4), so the amplitude falls with radius:
//   A_j = amplitude_rad (r_min / r_j)^stiffness_exponent (L_j / L_mean),
// r_min the thinnest joint's radius, L the joint's length (longer bones bend through more angle
// at the same curvature). w is the frequency rounded to a whole number of cycles over the
// duration, so the clip loops. Phases are drawn once per axis from the seeded generator and
// shared by the joints of that axis, so a branch sways as one piece.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "graphics/skeleton_skin.hpp"

namespace fspm::graphics {

struct WindOptions {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // horizontal part is used
  // Swing of the thinnest joint of mean length: 7 degrees.
  double amplitude_rad = 7.0 * std::numbers::pi / 180.0;
  double stiffness_exponent = 2.0;
  double bias = 0.3;  // share of the swing spent leaning with the wind
  double frequency_hz = 0.5;
  double duration_s = 4.0;
  double frames_per_second = 24.0;
  std::uint64_t seed = 1;

  // Throws ValueError for a vertical or zero wind, non-positive duration, frame rate or
  // frequency, or a negative amplitude.
  void validate() const;
};

struct JointSway {
  double amplitude_rad = 0.0;
  double phase_rad = 0.0;
  double overtone_phase_rad = 0.0;
};

struct WindAnimation {
  std::vector<float> times_s;                           // keyframe times, 0 .. duration
  std::vector<std::vector<Eigen::Quaternionf>> frames;  // frames[k][joint]
  Eigen::Vector3f axis = Eigen::Vector3f::UnitY();      // up x wind
};

// Amplitude and phases per joint.
std::vector<JointSway> joint_sways(const Skeleton& skeleton, const WindOptions& options,
                                   std::mt19937_64& rng);

// The frequency actually played: a whole number (at least 1) of cycles over the duration.
double looping_frequency_hz(const WindOptions& options);

// Rotation of one joint at time t.
Eigen::Quaternionf sway_rotation(const JointSway& sway, const Eigen::Vector3f& axis, double t_s,
                                 const WindOptions& options);

// The horizontal axis across the wind, up x wind (unit length).
Eigen::Vector3f sway_axis(const WindOptions& options);

// Joint rotations at time t of the animation wind_animation makes with the same options.
std::vector<Eigen::Quaternionf> wind_pose(const Skeleton& skeleton, const WindOptions& options,
                                          double t_s);

// Keyframes at frames_per_second from 0 to the duration inclusive (the last equals the first).
WindAnimation wind_animation(const Skeleton& skeleton, const WindOptions& options);

}  // namespace fspm::graphics
