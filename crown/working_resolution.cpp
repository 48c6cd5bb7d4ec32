#include "crown/working_resolution.hpp"

#include <algorithm>
#include <vector>

#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

// Sums over one block of the photograph: all pixels, crown pixels, foliage pixels and colours.
struct BlockSums {
  double pixels = 0.0, crown = 0.0, foliage = 0.0;
  double all_rgb[3] = {0.0, 0.0, 0.0}, foliage_rgb[3] = {0.0, 0.0, 0.0};
};

BlockSums block_sums(const Raster& photo, const Mask& mask, const Mask* foliage, int bx, int by,
                     int factor) {
  BlockSums s;
  const int x1 = std::min(photo.width, (bx + 1) * factor);
  const int y1 = std::min(photo.height, (by + 1) * factor);
  for (int y = by * factor; y < y1; ++y) {
    for (int x = bx * factor; x < x1; ++x) {
      const bool leaf = foliage == nullptr || foliage->at(x, y);
      s.pixels += 1.0;
      s.crown += mask.at(x, y);
      s.foliage += leaf;
      for (int c = 0; c < 3; ++c) {
        s.all_rgb[c] += photo.at(x, y, c);
        if (leaf) s.foliage_rgb[c] += photo.at(x, y, c);
      }
    }
  }
  return s;
}

}  // namespace

int working_factor(const Mask& mask, int max_side) {
  if (max_side < 16) throw ValueError("the working resolution must be at least 16 pixels");
  int x0 = mask.width, x1 = -1, y0 = mask.height, y1 = -1;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y)) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = y;
    }
  }
  if (x1 < 0) throw ValueError("the crown mask has no crown pixel");
  const int side = std::max(x1 - x0 + 1, y1 - y0 + 1);
  return (side + max_side - 1) / max_side;
}

WorkingImages working_images(const Raster& photo, const Mask& mask, const Mask* foliage,
                             int max_side) {
  WorkingImages w;
  w.factor = working_factor(mask, max_side);
  if (w.factor == 1) {
    w.photo = photo;
    w.mask = mask;
    w.foliage = foliage != nullptr ? *foliage : mask;
    return w;
  }
  const int f = w.factor;
  const int width = (photo.width + f - 1) / f, height = (photo.height + f - 1) / f;
  w.photo = Raster(width, height, 3);
  w.mask = Mask(width, height);
  w.coverage = Raster(width, height, 1);
  w.foliage = Mask(width, height);
  for (int by = 0; by < height; ++by) {
    for (int bx = 0; bx < width; ++bx) {
      const BlockSums s = block_sums(photo, mask, foliage, bx, by, f);
      w.coverage.at(bx, by) = static_cast<float>(s.crown / s.pixels);
      w.mask.set(bx, by, 2.0 * s.crown >= s.pixels);
      w.foliage.set(bx, by, s.foliage > 0.0);
      for (int c = 0; c < 3; ++c) {
        w.photo.at(bx, by, c) = static_cast<float>(s.foliage > 0.0 ? s.foliage_rgb[c] / s.foliage
                                                                   : s.all_rgb[c] / s.pixels);
      }
    }
  }
  if (w.mask.count() == 0) throw ValueError("the crown mask is too thin to reconstruct");
  return w;
}

}  // namespace fspm::crown
