#include "environment/sky_occlusion_kernel.hpp"

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "environment/simd_target.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// A random sky and caps, in the precision T. Every cap's rim lies at least kRimGap from every
// direction (in exact-enough double arithmetic), so whether a direction is inside a cap does not
// depend on how its dot product is rounded (error below 3 ulp of T, at most 4e-7 for float).
constexpr double kRimGap = 1e-4;

template <typename T>
struct Case {
  std::vector<T> x, y, z, vis;
  std::vector<OccludingCap<T>> caps;
};

template <typename T>
Case<T> random_case(std::mt19937_64& rng, std::size_t directions, std::size_t caps) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto unit = [&] {
    Eigen::Vector3d v;
    do {
      v = {normal(rng), normal(rng), normal(rng)};
    } while (v.norm() < 1e-3);
    return Eigen::Vector3d(v.normalized());
  };
  Case<T> c;
  for (std::size_t i = 0; i < directions; ++i) {
    const Eigen::Vector3d d = unit();
    c.x.push_back(static_cast<T>(d.x()));
    c.y.push_back(static_cast<T>(d.y()));
    c.z.push_back(static_cast<T>(d.z()));
    c.vis.push_back(static_cast<T>(0.5 + 0.5 * u(rng)));
  }
  for (std::size_t k = 0; k < caps; ++k) {
    const Eigen::Vector3d a = unit();
    OccludingCap<T> cap{static_cast<T>(a.x()), static_cast<T>(a.y()), static_cast<T>(a.z()), 0, 0};
    bool clear = false;
    while (!clear) {
      cap.cos_a = static_cast<T>(-0.3 + 1.29 * u(rng));
      clear = true;
      for (std::size_t i = 0; i < directions && clear; ++i) {
        const double dot =
            double(c.x[i]) * cap.axis_x + double(c.y[i]) * cap.axis_y + double(c.z[i]) * cap.axis_z;
        clear = std::abs(dot - double(cap.cos_a)) >= kRimGap;
      }
    }
    cap.gamma = static_cast<T>(u(rng));
    c.caps.push_back(cap);
  }
  return c;
}

// The oracle: the definition, one direction and one cap at a time.
template <typename T>
std::vector<T> plain_occlusion(const Case<T>& c) {
  std::vector<T> vis = c.vis;
  for (std::size_t i = 0; i < vis.size(); ++i) {
    for (const OccludingCap<T>& cap : c.caps) {
      if (c.x[i] * cap.axis_x + c.y[i] * cap.axis_y + c.z[i] * cap.axis_z >= cap.cos_a) {
        vis[i] *= cap.gamma;
      }
    }
  }
  return vis;
}

// Every target of this processor against the plain loop on seeded random skies: sizes around
// every vector width (1-16 lanes, blocks of four vectors, partial tails) and 0-40 caps.
// Tolerance: a direction's visibility is its start value times the gammas of the caps holding it
// (membership is exact, see kRimGap); k multiplications round k times, so any order of them stays
// within (k + 1) ulp relative of another. The kernel multiplies in the loop's order, so in fact
// the results agree bit for bit; the bound only keeps the test about rounding, not about order.
template <typename T>
void expect_every_target_matches_plain_loop(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  const std::vector<std::string> targets = simd_targets();
  ASSERT_FALSE(targets.empty());
  const T eps = std::numeric_limits<T>::epsilon();
  for (const std::size_t n :
       {1, 2, 3, 5, 7, 8, 9, 15, 16, 17, 31, 32, 33, 63, 64, 65, 100, 128, 255, 256, 257}) {
    for (const std::size_t k : {0, 1, 2, 5, 13, 40}) {
      const Case<T> c = random_case<T>(rng, n, k);
      const std::vector<T> want = plain_occlusion(c);
      for (const std::string& t : targets) {
        set_simd_target(t);
        ASSERT_EQ(sky_occlusion_target(), t);
        std::vector<T> got = c.vis;
        occlude_by_caps(std::span<T>(got), {c.x.data(), c.y.data(), c.z.data()}, c.caps);
        for (std::size_t i = 0; i < n; ++i) {
          ASSERT_NEAR(got[i], want[i], T(k + 1) * eps * want[i])
              << "target " << t << ", " << n << " directions, " << k << " caps, direction " << i;
        }
      }
    }
  }
  set_simd_target("best");
}

TEST(SkyOcclusionKernel, EveryTargetMatchesThePlainLoopInDoublePrecision) {
  expect_every_target_matches_plain_loop<double>(11);
}

TEST(SkyOcclusionKernel, EveryTargetMatchesThePlainLoopInSinglePrecision) {
  expect_every_target_matches_plain_loop<float>(12);
}

// A direction exactly on the rim (d . axis == cos_a, all products exact) is inside, on every
// target, as the light models' ray tests count it.
TEST(SkyOcclusionKernel, DirectionOnTheRimIsInsideOnEveryTarget) {
  const std::vector<double> x(9, 0.0), y(9, 0.0), z(9, 0.5);
  const std::vector<OccludingCap<double>> caps{{0.0, 0.0, 1.0, 0.5, 0.25}};
  for (const std::string& t : simd_targets()) {
    set_simd_target(t);
    std::vector<double> vis(9, 1.0);
    occlude_by_caps(std::span<double>(vis), {x.data(), y.data(), z.data()}, caps);
    for (const double v : vis) EXPECT_EQ(v, 0.25) << "target " << t;
  }
  set_simd_target("best");
}

TEST(SkyOcclusionKernel, BestTargetIsChosenByDefaultAndUnknownNamesAreRejected) {
  set_simd_target("best");
  EXPECT_EQ(sky_occlusion_target(), simd_targets().front());
  EXPECT_THROW(set_simd_target("avx9000"), ValueError);
  EXPECT_EQ(sky_occlusion_target(), simd_targets().front());  // a rejected name changes nothing
  const std::vector<std::string> targets = simd_targets();
  // The portable target answers to both of Highway's names for it; names ignore case.
  const std::string portable = targets.back();
  ASSERT_TRUE(portable == "scalar" || portable == "emu128") << portable;
  set_simd_target("EMU128");
  EXPECT_EQ(sky_occlusion_target(), portable);
  set_simd_target("Scalar");
  EXPECT_EQ(sky_occlusion_target(), portable);
  set_simd_target("best");
}

}  // namespace
}  // namespace fspm::environment
