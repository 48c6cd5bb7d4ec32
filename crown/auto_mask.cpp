#include "crown/auto_mask.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "crown/mask_morphology.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

// Median colour of the `band` pixels at each end of row y.
std::array<float, 3> row_background(const Raster& rgb, int y, int band) {
  std::array<float, 3> out{};
  for (int c = 0; c < 3; ++c) {
    std::vector<float> v;
    for (int i = 0; i < band; ++i) {
      v.push_back(rgb.at(i, y, c));
      v.push_back(rgb.at(rgb.width - 1 - i, y, c));
    }
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    out[static_cast<std::size_t>(c)] = v[v.size() / 2];
  }
  return out;
}

}  // namespace

Mask foreground(const Raster& rgb, float threshold) {
  Mask raw(rgb.width, rgb.height);
  const int band = std::max(1, rgb.width / 32);
  for (int y = 0; y < rgb.height; ++y) {
    const std::array<float, 3> bg = row_background(rgb, y, band);
    for (int x = 0; x < rgb.width; ++x) {
      float d2 = 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float d = rgb.at(x, y, c) - bg[static_cast<std::size_t>(c)];
        d2 += d * d;
      }
      raw.set(x, y, std::sqrt(d2) > threshold);
    }
  }
  return raw;
}

Mask auto_mask(const Raster& rgb, const AutoMaskOptions& options, const std::string& source) {
  const Mask raw = foreground(rgb, options.threshold);
  const int open = options.open_px > 0 ? options.open_px : std::max(1, rgb.height / 100);
  const int close = options.close_px > 0 ? options.close_px : std::max(1, rgb.height / 50);
  Mask m = erode(dilate(raw, close), close);  // closing: gaps between leaf clumps close
  m = dilate(erode(m, open), open);           // opening: trunk and thin branches go
  m = large_pieces(fill_holes(m), 0.1);
  if (m.count() == 0) {
    throw ValueError(
        "no crown found: nothing differs from the sky and ground beside it (give --mask)", source);
  }
  return m;
}

}  // namespace fspm::crown
