#include "crown/color_cubemap.hpp"

#include <algorithm>

namespace fspm::crown {
namespace {

// The lateral strip column and the distance (rows into the top or bottom face) of texel (x, y)
// of the top (face 4) or bottom (face 5) face, seen from its nearest edge.
void nearest_edge(int face, int x, int y, int n, int& column, int& distance) {
  const int to_front = face == 4 ? n - 1 - y : y;  // the front face is below the top face
  const int to_back = face == 4 ? y : n - 1 - y;
  const int to_right = n - 1 - x, to_left = x;
  distance = std::min({to_front, to_back, to_right, to_left});
  const int along_right = face == 4 ? n - 1 - y : y;  // right face column (its u is +y)
  if (distance == to_front) {
    column = x;
  } else if (distance == to_right) {
    column = n + along_right;
  } else if (distance == to_back) {
    column = 2 * n + (n - 1 - x);
  } else {
    column = 3 * n + (n - 1 - along_right);
  }
}

// Blends the band of `face` (4 top, 5 bottom) into the strip rows beyond the lateral faces.
void feather(Raster& face_image, int face, const Raster& strip, int n, int band) {
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      int column = 0, distance = 0;
      nearest_edge(face, x, y, n, column, distance);
      if (distance >= band) continue;
      const int row = face == 4 ? band - 1 - distance : band + n + distance;
      const float w = static_cast<float>(distance + 1) / static_cast<float>(band + 1);
      for (int c = 0; c < 3; ++c) {
        face_image.at(x, y, c) = w * face_image.at(x, y, c) + (1.0f - w) * strip.at(column, row, c);
      }
    }
  }
}

}  // namespace

Raster tileable_strip(const Raster& strip, int band) {
  const int width = strip.width - band;
  std::vector<float> errors(static_cast<std::size_t>(strip.height) * band);
  for (int y = 0; y < strip.height; ++y) {
    for (int j = 0; j < band; ++j) {
      float e = 0.0f;
      for (int c = 0; c < 3; ++c) {
        const float d = strip.at(width + j, y, c) - strip.at(j, y, c);
        e += d * d;
      }
      errors[static_cast<std::size_t>(y) * band + j] = e;
    }
  }
  const std::vector<int> cut = min_error_cut(errors, strip.height, band);
  Raster out(width, strip.height, 3);
  for (int y = 0; y < strip.height; ++y) {
    for (int x = 0; x < width; ++x) {
      // Left of the seam the head takes the tail's pixels, which continue the strip's end.
      const int sx = x < cut[static_cast<std::size_t>(y)] ? width + x : x;
      for (int c = 0; c < 3; ++c) out.at(x, y, c) = strip.at(sx, y, c);
    }
  }
  return out;
}

Cubemap color_cubemap(const Raster& rgb, const Mask& mask, int size, const QuiltOptions& options,
                      std::mt19937_64& rng) {
  const int n = size, band = std::max(2, size / 8);
  const Raster strip =
      tileable_strip(quilt_texture(rgb, mask, 4 * n + band, n + 2 * band, options, rng), band);
  Cubemap cube(n, 3);
  for (int f = 0; f < 4; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        for (int c = 0; c < 3; ++c)
          cube.faces[static_cast<std::size_t>(f)].at(x, y, c) = strip.at(f * n + x, band + y, c);
      }
    }
  }
  for (int face : {4, 5}) {
    cube.faces[static_cast<std::size_t>(face)] = quilt_texture(rgb, mask, n, n, options, rng);
    feather(cube.faces[static_cast<std::size_t>(face)], face, strip, n, band);
  }
  return cube;
}

}  // namespace fspm::crown
