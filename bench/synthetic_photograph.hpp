#pragma once
// The synthetic photograph the crown benchmarks reconstruct, at any size: a sky graded from blue
// to pale, a ground band (the lowest fifth), a trunk, and a crown of five overlapping discs (a
// dense, round-lobed crown, Argudo 4.1.1) of speckled greens with one pixel in thirteen a gap
// showing the sky. Seeded, so every run sees the same picture.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "crown/raster.hpp"

namespace fspm::bench {

inline crown::Raster synthetic_photograph(int width, int height, unsigned seed = 5) {
  crown::Raster photo(width, height, 3);
  const int ground = static_cast<int>(0.8 * height);
  // Lobes: centre (x, y) as fractions of width and height, radius as a fraction of height.
  const std::array<std::array<double, 3>, 5> lobes = {{{0.5, 0.40, 0.24},
                                                       {0.38, 0.48, 0.16},
                                                       {0.63, 0.47, 0.17},
                                                       {0.5, 0.25, 0.15},
                                                       {0.42, 0.30, 0.12}}};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const double trunk_half = 0.01 * height;
  for (int y = 0; y < height; ++y) {
    const float t = static_cast<float>(y) / static_cast<float>(std::max(1, ground));
    for (int x = 0; x < width; ++x) {
      std::array<float, 3> c =
          y >= ground ? std::array<float, 3>{0.47f, 0.55f, 0.31f}
                      : std::array<float, 3>{0.67f + 0.16f * t, 0.78f + 0.12f * t, 0.94f};
      if (y > 0.45 * height && y < ground && std::abs(x - 0.5 * width) < trunk_half) {
        c = {0.35f, 0.24f, 0.16f};
      }
      bool crown = false;
      for (const auto& l : lobes) {
        const double dx = x - l[0] * width, dy = y - l[1] * height, r = l[2] * height;
        crown = crown || dx * dx + dy * dy <= r * r;
      }
      const float v = u(rng);
      if (crown && v > 1.0f / 13.0f) c = {0.1f + 0.2f * v, 0.24f + 0.43f * v, 0.08f + 0.14f * v};
      for (int k = 0; k < 3; ++k) photo.at(x, y, k) = c[static_cast<std::size_t>(k)];
    }
  }
  return photo;
}

}  // namespace fspm::bench
