#include "crown/gaussian_blur.hpp"

#include <cmath>
#include <vector>

namespace fspm::crown {
namespace {

std::vector<float> kernel(double sigma) {
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<float> k(static_cast<std::size_t>(2 * radius + 1));
  for (int i = -radius; i <= radius; ++i) {
    k[static_cast<std::size_t>(i + radius)] =
        static_cast<float>(std::exp(-0.5 * i * i / (sigma * sigma)));
  }
  return k;
}

// One pass along x (horizontal) or y of both the weighted values and the weights.
void pass(const Raster& in, const Raster& weight_in, Raster& out, Raster& weight_out,
          const std::vector<float>& k, bool horizontal) {
  const int radius = static_cast<int>(k.size() / 2);
  for (int y = 0; y < in.height; ++y) {
    for (int x = 0; x < in.width; ++x) {
      float sum = 0.0f, weight = 0.0f;
      for (int i = -radius; i <= radius; ++i) {
        const int sx = horizontal ? x + i : x;
        const int sy = horizontal ? y : y + i;
        if (!in.contains(sx, sy)) continue;
        const float w = k[static_cast<std::size_t>(i + radius)];
        sum += w * in.at(sx, sy);
        weight += w * weight_in.at(sx, sy);
      }
      out.at(x, y) = sum;
      weight_out.at(x, y) = weight;
    }
  }
}

}  // namespace

Raster masked_gaussian_blur(const Raster& image, const Mask& mask, double sigma) {
  const std::vector<float> k = kernel(sigma);
  Raster value(image.width, image.height, 1), weight(image.width, image.height, 1);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float m = mask.at(x, y) ? 1.0f : 0.0f;
      weight.at(x, y) = m;
      value.at(x, y) = m * image.at(x, y);
    }
  }
  Raster value2(image.width, image.height, 1), weight2(image.width, image.height, 1);
  pass(value, weight, value2, weight2, k, true);
  pass(value2, weight2, value, weight, k, false);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const float w = weight.at(x, y);
      value.at(x, y) = mask.at(x, y) && w > 0.0f ? value.at(x, y) / w : 0.0f;
    }
  }
  return value;
}

}  // namespace fspm::crown
