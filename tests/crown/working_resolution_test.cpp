// The working resolution (crown/working_resolution.hpp) against closed forms and brute force:
// block means and gaps, a border kept at the photograph's accuracy through the blocks' coverage,
// a large disc still inflating to its sphere, and the running-count morphology against the
// plain square window.
#include "crown/working_resolution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "crown/crown_from_photo.hpp"
#include "crown/inflation.hpp"
#include "crown/mask_morphology.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

Mask disc(int size, double centre, double radius) {
  Mask m(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      m.set(x, y, (x - centre) * (x - centre) + (y - centre) * (y - centre) <= radius * radius);
    }
  }
  return m;
}

TEST(WorkingResolution, FactorBringsTheCrownWithinTheLongerSide) {
  Mask m(1000, 600);
  for (int y = 100; y < 400; ++y) {
    for (int x = 50; x < 950; ++x) m.set(x, y, true);  // 900 x 300
  }
  EXPECT_EQ(working_factor(m, 512), 2);
  EXPECT_EQ(working_factor(m, 900), 1);
  EXPECT_EQ(working_factor(m, 899), 2);
  EXPECT_EQ(working_factor(m, 100), 9);
  EXPECT_THROW(working_factor(Mask(10, 10), 512), Error);
  EXPECT_THROW(working_factor(m, 8), Error);
}

// Blocks of 2 x 2: a block's colour is its foliage pixels' mean, a block without foliage is a gap
// taking all its pixels' mean, coverage is the share of crown pixels.
TEST(WorkingResolution, BlockMeansOfFoliageAndCoverage) {
  Raster photo(40, 40, 3);
  Mask mask(40, 40), foliage(40, 40);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      mask.set(x, y, !(x == 1 && y == 0));  // block (0, 0) has 3 crown pixels of 4
      foliage.set(x, y, !(x >= 2 && x < 4 && y < 2) && x != 0);  // block (1, 0): no foliage
      for (int c = 0; c < 3; ++c) photo.at(x, y, c) = 0.1f * static_cast<float>(x % 2 + c);
    }
  }
  const WorkingImages w = working_images(photo, mask, &foliage, 20);
  ASSERT_EQ(w.factor, 2);
  ASSERT_EQ(w.photo.width, 20);
  EXPECT_FLOAT_EQ(w.coverage.at(0, 0), 0.75f);
  EXPECT_TRUE(w.mask.at(0, 0));
  EXPECT_FLOAT_EQ(w.photo.at(0, 0, 0), 0.1f);  // only the x = 1 column is foliage
  EXPECT_FALSE(w.foliage.at(1, 0));
  EXPECT_FLOAT_EQ(w.photo.at(1, 0, 2), 0.25f);  // the mean of 0.2 and 0.3
  EXPECT_TRUE(w.foliage.at(2, 3));
}

// A disc of radius 900 pixels reduced 8 times: its silhouette vertices, placed from the blocks'
// coverage, lie on the circle of radius 900 to a fraction of a photograph pixel; placed on the
// reduced mask's own border they are several photograph pixels off.
TEST(WorkingResolution, CoverageKeepsTheBorderOfThePhotograph) {
  const Mask full = disc(2000, 999.5, 900.0);
  const WorkingImages w = working_images(Raster(2000, 2000, 3), full, nullptr, 256);
  ASSERT_EQ(w.factor, 8);
  auto border_error = [&](const InflatedSheet& s) {
    double sum = 0.0, n = 0.0;
    for (std::size_t p = 0; p < s.classes.size(); ++p) {
      if (s.classes[p] != PixelClass::kSilhouette) continue;
      const Eigen::Vector3d& q = s.positions[static_cast<std::size_t>(s.vertex[p])];
      // Working pixel centre b is the photograph's b f + (f - 1) / 2.
      const double x = q.x() * 8 + 3.5, y = q.y() * 8 + 3.5;
      sum += std::abs(std::hypot(x - 999.5, y - 999.5) - 900.0), n += 1.0;
    }
    return sum / n;
  };
  const double with = border_error(inflate(w.mask, {}, w.coverage));
  const double without = border_error(inflate(w.mask, {}));
  std::cout << "border error in photograph pixels: " << with << " from coverage, " << without
            << " from the reduced mask\n";
  EXPECT_LT(with, 0.5);
  EXPECT_GT(without, 2.0 * with);
}

// The disc of radius 1000 pixels, its crown 20 m high, reconstructed at the working resolution:
// the sphere of radius 10 m within 3 % in volume, as at the photograph's own resolution.
TEST(WorkingResolution, LargeDiscIsStillASphere) {
  const Mask full = disc(2048, 1023.5, 1000.0);
  const Raster photo(2048, 2048, 3, 0.3f);
  CrownOptions options;
  options.height_m = 20.0;
  std::mt19937_64 rng(1);
  const CrownModel model = reconstruct_crown(photo, full, options, rng);
  const double sphere = 4.0 / 3.0 * M_PI * 1000.0;
  std::cout << "working factor " << model.working_factor << ", volume " << model.volume_m3 / sphere
            << " of the sphere's\n";
  EXPECT_EQ(model.working_factor, 4);
  EXPECT_NEAR(model.metres_per_pixel, 0.01, 1e-4);
  EXPECT_NEAR(model.volume_m3 / sphere, 1.0, 0.03);
}

// Brute force: each output pixel the max (dilation) or min (erosion) over its square window,
// pixels past the border background for a dilation and crown for an erosion.
TEST(WorkingResolution, RunningCountMorphologyMatchesTheSquareWindow) {
  std::mt19937 rng(3);
  Mask m(37, 23);
  for (auto& v : m.inside) v = rng() % 3 == 0;
  for (int radius : {1, 2, 5}) {
    const Mask d = dilate(m, radius), e = erode(m, radius);
    for (int y = 0; y < m.height; ++y) {
      for (int x = 0; x < m.width; ++x) {
        bool any = false, all = true;
        for (int dy = -radius; dy <= radius; ++dy) {
          for (int dx = -radius; dx <= radius; ++dx) {
            const bool inside = m.contains(x + dx, y + dy);
            any = any || (inside && m.at(x + dx, y + dy));
            all = all && (!inside || m.at(x + dx, y + dy));
          }
        }
        ASSERT_EQ(d.at(x, y), any) << x << "," << y << " r " << radius;
        ASSERT_EQ(e.at(x, y), all) << x << "," << y << " r " << radius;
      }
    }
  }
}

}  // namespace
}  // namespace fspm::crown
