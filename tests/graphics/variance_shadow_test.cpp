// The Chebyshev bound of variance shadow maps (Pirk eq. 6.10-6.12) against values worked by hand.
#include "graphics/variance_shadow.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fspm::graphics {
namespace {

// A receiver no farther than the mean occluder is fully lit: the bound is one-sided.
TEST(VarianceShadow, ReceiverInFrontOfTheMeanIsLit) {
  EXPECT_EQ(chebyshev_upper_bound(0.5, 0.26, 0.4), 1.0);
  EXPECT_EQ(chebyshev_upper_bound(0.5, 0.26, 0.5), 1.0);
  EXPECT_EQ(variance_shadow_light(0.5, 0.26, 0.5), 1.0);
}

// mu = 0.5, sigma^2 = 0.26 - 0.25 = 0.01 (eq. 6.11). At t = 0.6: (t - mu)^2 = 0.01, p_max =
// 0.01 / 0.02 = 0.5; at t = 0.7: 0.01 / (0.01 + 0.04) = 0.2. The formula as printed, with
// (t - mu^2) = 0.35, would give 0.01 / 0.36 = 0.028.
TEST(VarianceShadow, BoundUsesTheSquaredDistanceToTheMean) {
  EXPECT_NEAR(chebyshev_upper_bound(0.5, 0.26, 0.6), 0.5, 1e-12);
  EXPECT_NEAR(chebyshev_upper_bound(0.5, 0.26, 0.7), 0.2, 1e-12);
  EXPECT_GT(std::abs(chebyshev_upper_bound(0.5, 0.26, 0.6) - 0.01 / 0.36), 0.4);
}

// The bound is tight for two depths: occluders at 0.3 over 70% of the filter region and 0.8 over
// 30% give M1 = 0.45, M2 = 0.7 * 0.09 + 0.3 * 0.64 = 0.255 (eq. 6.10), sigma^2 = 0.0525; a
// receiver at 0.8 sees (t - mu)^2 = 0.1225 and p_max = 0.0525 / 0.175 = 0.3, the share of the
// region not in front of it.
TEST(VarianceShadow, BoundIsTightForTwoDepths) {
  const double m1 = 0.7 * 0.3 + 0.3 * 0.8, m2 = 0.7 * 0.09 + 0.3 * 0.64;
  EXPECT_NEAR(chebyshev_upper_bound(m1, m2, 0.8), 0.3, 1e-12);
  // Farther receivers get less: a receiver at 1.0 is behind both, yet the bound keeps
  // 0.0525 / (0.0525 + 0.3025) = 0.1479 (the light bleeding of variance shadow maps).
  EXPECT_NEAR(chebyshev_upper_bound(m1, m2, 1.0), 0.0525 / 0.355, 1e-12);
}

// Zero variance (one flat occluder filling the region) is raised to the minimum: at mu = 0.3,
// t = 0.31, p_max = 2e-6 / (2e-6 + 1e-4) = 0.019608.
TEST(VarianceShadow, MinimumVarianceKeepsTheBoundFinite) {
  EXPECT_NEAR(chebyshev_upper_bound(0.3, 0.09, 0.31, 2e-6), 2e-6 / 1.02e-4, 1e-9);
  EXPECT_NEAR(chebyshev_upper_bound(0.3, 0.09, 0.31, 2e-6), 0.019608, 1e-6);
}

// Bleeding reduction with bleed = 0.2: p_max 0.5 -> (0.5 - 0.2) / 0.8 = 0.375; p_max 0.2 -> 0.
TEST(VarianceShadow, BleedReductionStretchesTheBound) {
  EXPECT_NEAR(variance_shadow_light(0.5, 0.26, 0.6, 2e-6, 0.2), 0.375, 1e-12);
  EXPECT_NEAR(variance_shadow_light(0.5, 0.26, 0.7, 2e-6, 0.2), 0.0, 1e-12);
  EXPECT_NEAR(variance_shadow_light(0.5, 0.26, 0.6, 2e-6, 0.0), 0.5, 1e-12);
}

}  // namespace
}  // namespace fspm::graphics
