#pragma once
// Pixel counts of rendered images, shared by the graphics and command-line render tests.
#include <algorithm>
#include <cstddef>

#include "graphics/image.hpp"

namespace fspm::graphics::testing {

// Grey pixels: an obstacle's stone under the light kit's warm key light (red >= blue); neither
// the white-to-blue background (blue > red) nor bark, leaves or grass (far from grey).
inline std::size_t stone_pixels(const Image& image) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
      if (hi - lo < 24 && p[0] >= p[2] && hi > 60 && hi < 235) ++n;
    }
  }
  return n;
}

}  // namespace fspm::graphics::testing
