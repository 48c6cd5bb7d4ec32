#include "crown/raster.hpp"

#include <algorithm>

namespace fspm::crown {

std::size_t Mask::count() const {
  return static_cast<std::size_t>(
      std::count_if(inside.begin(), inside.end(), [](std::uint8_t v) { return v != 0; }));
}

Raster luminance_of(const Raster& rgb) {
  Raster out(rgb.width, rgb.height, 1);
  for (int y = 0; y < rgb.height; ++y) {
    for (int x = 0; x < rgb.width; ++x) {
      out.at(x, y) = luminance(rgb.at(x, y, 0), rgb.at(x, y, 1), rgb.at(x, y, 2));
    }
  }
  return out;
}

}  // namespace fspm::crown
