// Relief from luminance (Argudo 4.4): the luminance weights, the blur pyramid of a flat image, and
// Poisson pasting against a closed form.
#include "crown/relief.hpp"

#include <gtest/gtest.h>

#include "crown/gaussian_blur.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

Mask square_mask(int size, int x0, int x1) {
  Mask m(size, size);
  for (int y = x0; y <= x1; ++y) {
    for (int x = x0; x <= x1; ++x) m.set(x, y, true);
  }
  return m;
}

TEST(Relief, LuminanceWeightsOfRec709) {
  EXPECT_FLOAT_EQ(luminance(1, 0, 0), 0.2126f);
  EXPECT_FLOAT_EQ(luminance(0, 1, 0), 0.7152f);
  EXPECT_FLOAT_EQ(luminance(0, 0, 1), 0.0722f);
  EXPECT_NEAR(luminance(1, 1, 1), 1.0f, 1e-6f);
}

TEST(Relief, MaskedBlurKeepsAConstantAndIgnoresTheOutside) {
  Raster image(32, 32, 1, 0.3f);
  const Mask mask = square_mask(32, 8, 23);
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      if (!mask.at(x, y)) image.at(x, y) = 1.0f;  // bright sky that must not bleed in
    }
  }
  const Raster b = masked_gaussian_blur(image, mask, 3.0);
  for (int y = 8; y <= 23; ++y) {
    for (int x = 8; x <= 23; ++x) EXPECT_NEAR(b.at(x, y), 0.3f, 1e-5f);
  }
  EXPECT_EQ(b.at(0, 0), 0.0f);
}

// With H = f + c where f vanishes on the pixels just outside the crown, the pasted field is f
// exactly: the discrete Poisson system is solved by it (Perez et al. with f* = 0).
TEST(Relief, PoissonPastingRecoversTheFieldThatVanishesOutside) {
  const int size = 40, x0 = 10, x1 = 29;
  const Mask mask = square_mask(size, x0, x1);
  auto f = [&](int x, int y) {
    return 1e-4 * (x - x0 + 1) * (x1 + 1 - x) * (y - x0 + 1) * (x1 + 1 - y);
  };
  Raster h(size, size, 1);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      h.at(x, y) = static_cast<float>(0.7 + (mask.at(x, y) ? f(x, y) : 0.0));
    }
  }
  // Outside the crown H is the constant only where f would be 0: the pixels next to the crown.
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      if (!mask.at(x, y)) h.at(x, y) = static_cast<float>(0.7 + f(x, y));
    }
  }
  const Raster pasted = paste_on_plane(h, mask);
  for (int y = x0; y <= x1; ++y) {
    for (int x = x0; x <= x1; ++x) EXPECT_NEAR(pasted.at(x, y), f(x, y), 1e-5) << x << "," << y;
  }
  EXPECT_EQ(pasted.at(5, 5), 0.0f);
}

TEST(Relief, DarkerPixelsAreLowerInTheHeightfield) {
  Raster rgb(32, 32, 3, 0.6f);
  for (int y = 12; y < 20; ++y) {
    for (int x = 12; x < 20; ++x) {
      for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = 0.1f;  // a dark pit in the crown's middle
    }
  }
  Mask all(32, 32);
  all.inside.assign(all.inside.size(), 1);
  const Raster h = luminance_heightfield(rgb, all, {});
  EXPECT_LT(h.at(16, 16), h.at(3, 3));
  EXPECT_GE(h.at(16, 16), 0.0f);
  EXPECT_LE(h.at(3, 3), 1.0f);
  EXPECT_THROW(luminance_heightfield(rgb, all, {0, 1.0}), Error);
}

}  // namespace
}  // namespace fspm::crown
