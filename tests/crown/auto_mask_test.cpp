// The automatic crown mask on a synthetic photograph: graded sky, ground, a speckled crown on a
// thin trunk. The crown's disc must come back, the trunk and the background must not.
#include "crown/auto_mask.hpp"

#include <gtest/gtest.h>

#include <random>

#include "crown/mask_morphology.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

TEST(AutoMask, FindsTheCrownDiscWithoutTrunkOrBackground) {
  const int n = 200;
  Raster rgb(n, n, 3);
  std::mt19937_64 rng(2);
  std::bernoulli_distribution gap(0.15);  // sky seen through the foliage
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const float t = static_cast<float>(y) / n;
      float r = 0.55f + 0.3f * t, g = 0.7f + 0.2f * t, b = 0.95f;  // sky, lighter downward
      if (y >= 170) r = 0.45f, g = 0.5f, b = 0.3f;                 // ground
      const bool in_crown = (x - 100) * (x - 100) + (y - 80) * (y - 80) <= 50 * 50;
      if (std::abs(x - 100) <= 1 && y > 80 && y < 170) r = 0.4f, g = 0.28f, b = 0.15f;  // trunk
      if (in_crown && !gap(rng)) r = 0.1f, g = 0.25f, b = 0.08f;
      rgb.at(x, y, 0) = r, rgb.at(x, y, 1) = g, rgb.at(x, y, 2) = b;
    }
  }
  const Mask m = auto_mask(rgb, {});
  std::size_t disc = 0, both = 0, either = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const bool in_disc = (x - 100) * (x - 100) + (y - 80) * (y - 80) <= 50 * 50;
      disc += in_disc;
      both += in_disc && m.at(x, y);
      either += in_disc || m.at(x, y);
    }
  }
  EXPECT_GT(static_cast<double>(both) / static_cast<double>(either), 0.95);
  EXPECT_FALSE(m.at(100, 150));  // the trunk
  EXPECT_FALSE(m.at(10, 10));    // sky
  EXPECT_FALSE(m.at(10, 190));   // ground
}

TEST(AutoMask, EmptyPictureHasNoCrown) {
  Raster rgb(64, 64, 3, 0.5f);
  EXPECT_THROW(auto_mask(rgb, {}), ValueError);
}

TEST(MaskMorphology, FillsHolesAndDropsSmallPieces) {
  Mask m(20, 20);
  for (int y = 2; y < 12; ++y) {
    for (int x = 2; x < 12; ++x) m.set(x, y, x == 2 || x == 11 || y == 2 || y == 11);
  }
  m.set(16, 16, true);  // a speck
  const Mask filled = fill_holes(m);
  EXPECT_TRUE(filled.at(6, 6));
  const Mask kept = large_pieces(filled, 0.1);
  EXPECT_TRUE(kept.at(6, 6));
  EXPECT_FALSE(kept.at(16, 16));
  EXPECT_EQ(kept.count(), 100u);
}

}  // namespace
}  // namespace fspm::crown
