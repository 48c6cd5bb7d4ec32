#pragma once
// Cubemaps of a crown seen from its centre (Argudo 4.5.2, 4.6), z up. Faces in the order
// front (-y, toward the camera of the photograph), right (+x), back (+y), left (-x), top (+z),
// bottom (-z). Lateral faces are seen from outside with z up, so the four of them side by side
// form one continuous strip around the crown; the top face has the front face below it, the
// bottom face has the front face above it.
#include <Eigen/Core>
#include <array>

#include "crown/raster.hpp"

namespace fspm::crown {

inline constexpr int kCubeFaces = 6;

struct Cubemap {
  int size = 0;  // N: pixels on a face's side
  std::array<Raster, kCubeFaces> faces;

  Cubemap() = default;
  Cubemap(int n, int channels);
};

struct CubeTexel {
  int face = 0;
  int x = 0;  // column
  int y = 0;  // row, 0 at the top
};

// Unit direction through the centre of texel (x, y) of `face`.
Eigen::Vector3f texel_direction(int face, float x, float y, int size);
// The texel a direction (not zero) falls in.
CubeTexel direction_texel(const Eigen::Vector3f& direction, int size);

// The six faces side by side (6N x N), in face order, as one image file.
Raster cubemap_strip(const Cubemap& cubemap);
// The faces of such a strip (6N x N; throws ValueError for another shape).
Cubemap cubemap_from_strip(const Raster& strip);

}  // namespace fspm::crown
