#include "crown/gap_fill.hpp"

#include "crown/gaussian_blur.hpp"

namespace fspm::crown {
namespace {

// Channel c of `rgb` times the foliage indicator, or the indicator itself for c < 0.
Raster weighted_channel(const Raster& rgb, const Mask& source, int c) {
  Raster out(rgb.width, rgb.height, 1);
  for (int y = 0; y < rgb.height; ++y) {
    for (int x = 0; x < rgb.width; ++x) {
      out.at(x, y) = source.at(x, y) ? (c < 0 ? 1.0f : rgb.at(x, y, c)) : 0.0f;
    }
  }
  return out;
}

}  // namespace

Raster fill_gaps(const Raster& rgb, const Mask& crown, const Mask& foliage) {
  Raster out = rgb;
  Mask source(rgb.width, rgb.height), unfilled(rgb.width, rgb.height), all(rgb.width, rgb.height);
  all.inside.assign(all.inside.size(), 1);
  for (int y = 0; y < rgb.height; ++y) {
    for (int x = 0; x < rgb.width; ++x) {
      source.set(x, y, crown.at(x, y) && foliage.at(x, y));
      unfilled.set(x, y, crown.at(x, y) && !foliage.at(x, y));
    }
  }
  if (source.count() == 0) return out;
  // Normalized convolution: blur(colour x foliage) / blur(foliage), wider until all gaps are met.
  for (double sigma = 2.0; unfilled.count() > 0 && sigma < 2.0 * (rgb.width + rgb.height);
       sigma *= 2.0) {
    const Raster weight = masked_gaussian_blur(weighted_channel(rgb, source, -1), all, sigma);
    Raster channels[3];
    for (int c = 0; c < 3; ++c) {
      channels[c] = masked_gaussian_blur(weighted_channel(rgb, source, c), all, sigma);
    }
    for (int y = 0; y < rgb.height; ++y) {
      for (int x = 0; x < rgb.width; ++x) {
        if (!unfilled.at(x, y) || weight.at(x, y) < 1e-3f) continue;
        for (int c = 0; c < 3; ++c) out.at(x, y, c) = channels[c].at(x, y) / weight.at(x, y);
        unfilled.set(x, y, false);
      }
    }
  }
  return out;
}

}  // namespace fspm::crown
