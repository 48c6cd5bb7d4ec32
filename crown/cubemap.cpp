#include "crown/cubemap.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/error.hpp"

namespace fspm::crown {

Cubemap::Cubemap(int n, int channels) : size(n) {
  for (Raster& f : faces) f = Raster(n, n, channels);
}

Eigen::Vector3f texel_direction(int face, float x, float y, int size) {
  const float u = 2.0f * (x + 0.5f) / static_cast<float>(size) - 1.0f;  // right
  const float v = 2.0f * (y + 0.5f) / static_cast<float>(size) - 1.0f;  // down
  Eigen::Vector3f d;
  switch (face) {
    case 0:
      d = {u, -1.0f, -v};
      break;
    case 1:
      d = {1.0f, u, -v};
      break;
    case 2:
      d = {-u, 1.0f, -v};
      break;
    case 3:
      d = {-1.0f, -u, -v};
      break;
    case 4:
      d = {u, -v, 1.0f};
      break;
    default:
      d = {u, v, -1.0f};
      break;
  }
  return d.normalized();
}

CubeTexel direction_texel(const Eigen::Vector3f& d, int size) {
  const Eigen::Vector3f a = d.cwiseAbs();
  int face;
  float u, v;  // in [-1, 1], inverting texel_direction
  if (a.z() >= a.x() && a.z() >= a.y()) {
    face = d.z() > 0.0f ? 4 : 5;
    u = d.x() / a.z();
    v = face == 4 ? -d.y() / a.z() : d.y() / a.z();
  } else if (a.x() >= a.y()) {
    face = d.x() > 0.0f ? 1 : 3;
    u = face == 1 ? d.y() / a.x() : -d.y() / a.x();
    v = -d.z() / a.x();
  } else {
    face = d.y() < 0.0f ? 0 : 2;
    u = face == 0 ? d.x() / a.y() : -d.x() / a.y();
    v = -d.z() / a.y();
  }
  auto texel = [size](float t) {
    return std::clamp(static_cast<int>(std::floor(0.5f * (t + 1.0f) * size)), 0, size - 1);
  };
  return {face, texel(u), texel(v)};
}

Raster cubemap_strip(const Cubemap& cubemap) {
  const int n = cubemap.size, c = cubemap.faces[0].channels;
  Raster out(kCubeFaces * n, n, c);
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        for (int k = 0; k < c; ++k)
          out.at(f * n + x, y, k) = cubemap.faces[static_cast<std::size_t>(f)].at(x, y, k);
      }
    }
  }
  return out;
}

Cubemap cubemap_from_strip(const Raster& strip) {
  const int n = strip.height;
  if (n < 1 || strip.width != kCubeFaces * n) {
    throw ValueError("expected a cubemap strip of 6N x N pixels, got " +
                     std::to_string(strip.width) + " x " + std::to_string(strip.height));
  }
  Cubemap out(n, strip.channels);
  for (int f = 0; f < kCubeFaces; ++f) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        for (int k = 0; k < strip.channels; ++k)
          out.faces[static_cast<std::size_t>(f)].at(x, y, k) = strip.at(f * n + x, y, k);
      }
    }
  }
  return out;
}

}  // namespace fspm::crown
