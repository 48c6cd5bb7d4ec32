#pragma once
// Rasters of the crown pipeline, row 0 at the top: a float image with any number of channels
// (RGB in [0, 1], luminance, heights) and a crown mask (1 inside the crown).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fspm::crown {

struct Raster {
  int width = 0;
  int height = 0;
  int channels = 1;
  std::vector<float> values;  // width * height * channels, interleaved

  Raster() = default;
  Raster(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), values(static_cast<std::size_t>(w) * h * c, fill) {}

  std::size_t index(int x, int y, int c = 0) const {
    return (static_cast<std::size_t>(y) * width + x) * channels + c;
  }
  float& at(int x, int y, int c = 0) { return values[index(x, y, c)]; }
  float at(int x, int y, int c = 0) const { return values[index(x, y, c)]; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

struct Mask {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> inside;  // width * height, 1 = crown

  Mask() = default;
  Mask(int w, int h) : width(w), height(h), inside(static_cast<std::size_t>(w) * h, 0) {}

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  // False outside the raster, so stencils may look past the border.
  bool at(int x, int y) const {
    return contains(x, y) && inside[static_cast<std::size_t>(y) * width + x] != 0;
  }
  void set(int x, int y, bool v) { inside[static_cast<std::size_t>(y) * width + x] = v ? 1 : 0; }
  std::size_t count() const;
};

// Relative luminance of linear RGB (Argudo 4.4; ITU-R BT.709 weights).
inline float luminance(float r, float g, float b) {
  return 0.2126f * r + 0.7152f * g + 0.0722f * b;
}

// The luminance channel of an RGB raster.
Raster luminance_of(const Raster& rgb);

}  // namespace fspm::crown
