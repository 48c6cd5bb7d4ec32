#include "crown/silhouette.hpp"

namespace fspm::crown {

std::vector<PixelClass> classify_pixels(const Mask& mask, Connectivity connectivity) {
  std::vector<PixelClass> out(mask.inside.size(), PixelClass::kOutside);
  const bool diagonals = connectivity == Connectivity::kFour;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      if (!mask.at(x, y)) continue;
      bool border = false;
      for (int dy = -1; dy <= 1 && !border; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (!diagonals && dx != 0 && dy != 0)) continue;
          if (!mask.at(x + dx, y + dy)) {
            border = true;
            break;
          }
        }
      }
      out[static_cast<std::size_t>(y) * mask.width + x] =
          border ? PixelClass::kSilhouette : PixelClass::kInner;
    }
  }
  return out;
}

}  // namespace fspm::crown
