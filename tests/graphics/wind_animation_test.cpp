// Wind sway: amplitudes against the closed form, the axis across the wind, looping, seeds.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "fspm/error.hpp"
#include "graphics/wind_animation.hpp"
#include "tests/graphics/test_trees.hpp"

namespace fspm::graphics {
namespace {

float angle_of(const Eigen::Quaternionf& q) {
  return 2.0f * std::acos(std::min(1.0f, std::abs(q.w())));
}

TEST(WindAnimation, AmplitudeFallsWithTheSquareOfTheRadius) {
  // bias 1: every joint leans by its amplitude A_j = A (r_min / r_j)^2 (L_j / L_mean) at all
  // times. Junction tree: trunk r = 0.1, L = 1 (4 joints); laterals r = 0.03, L = 0.6 (4 joints);
  // L_mean = 0.8.
  const Skeleton s = tree_skeleton(testing::junction_tree());
  WindOptions o;
  o.bias = 1.0;
  o.amplitude_rad = 0.2;
  o.direction = {1.0, 1.0, 0.0};
  const WindAnimation a = wind_animation(s, o);
  const float trunk = 0.2 * std::pow(0.03 / 0.1, 2.0) * (1.0 / 0.8);
  const float lateral = 0.2 * (0.6 / 0.8);
  for (const auto& frame : a.frames) {
    for (std::size_t j = 0; j < s.size(); ++j) {
      EXPECT_NEAR(angle_of(frame[j]), s.radii_m[j] > 0.05f ? trunk : lateral, 1e-5f);
    }
  }
  // The bending axis is horizontal and across the wind: z x (1, 1, 0) / sqrt 2.
  const Eigen::Vector3f axis = Eigen::AngleAxisf(a.frames[0][0]).axis();
  EXPECT_TRUE(axis.isApprox(Eigen::Vector3f(-1, 1, 0).normalized(), 1e-5f)) << axis.transpose();
}

TEST(WindAnimation, LoopsAndDependsOnlyOnTheSeed) {
  const Skeleton s = tree_skeleton(testing::junction_tree());
  WindOptions o;
  o.duration_s = 3.0;
  o.frequency_hz = 0.45;  // played at 1 / 3 * round(1.35) = 1/3 Hz, a whole cycle
  o.frames_per_second = 8.0;
  EXPECT_DOUBLE_EQ(looping_frequency_hz(o), 1.0 / 3.0);
  const WindAnimation a = wind_animation(s, o);
  ASSERT_EQ(a.times_s.size(), 25u);
  EXPECT_FLOAT_EQ(a.times_s.back(), 3.0f);
  for (std::size_t j = 0; j < s.size(); ++j) {
    EXPECT_TRUE(a.frames.front()[j].isApprox(a.frames.back()[j], 1e-5f));
  }
  const WindAnimation same = wind_animation(s, o);
  o.seed = 2;
  const WindAnimation other = wind_animation(s, o);
  bool differs = false;
  for (std::size_t k = 0; k < a.frames.size(); ++k) {
    for (std::size_t j = 0; j < s.size(); ++j) {
      EXPECT_EQ(a.frames[k][j].coeffs(), same.frames[k][j].coeffs());
      differs |= !a.frames[k][j].isApprox(other.frames[k][j], 1e-4f);
    }
  }
  EXPECT_TRUE(differs);
  // The four trunk joints share one axis (and radius and length): they sway together.
  for (const auto& frame : a.frames) {
    for (std::size_t j = 1; j < 4; ++j) EXPECT_EQ(frame[j].coeffs(), frame[0].coeffs());
  }
}

TEST(WindAnimation, RejectsVerticalWindAndBadTimes) {
  const Skeleton s = tree_skeleton(testing::junction_tree());
  WindOptions o;
  o.direction = {0.0, 0.0, 1.0};
  EXPECT_THROW(wind_animation(s, o), ValueError);
  o = {};
  o.duration_s = 0.0;
  EXPECT_THROW(wind_animation(s, o), ValueError);
  o = {};
  o.frames_per_second = std::nan("");
  EXPECT_THROW(wind_animation(s, o), ValueError);
}

}  // namespace
}  // namespace fspm::graphics
