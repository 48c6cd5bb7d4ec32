#include "crown/radius_cubemap.hpp"

#include <vector>

#include "crown/relief.hpp"

namespace fspm::crown {
namespace {

// Fills texels < 0 with the mean of their non-negative 4-neighbours on the same face.
void fill_holes(Raster& face) {
  for (int pass = 0; pass < face.width + face.height; ++pass) {
    Raster next = face;
    bool missing = false;
    for (int y = 0; y < face.height; ++y) {
      for (int x = 0; x < face.width; ++x) {
        if (face.at(x, y) >= 0.0f) continue;
        float sum = 0.0f;
        int count = 0;
        for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          if (face.contains(x + dx, y + dy) && face.at(x + dx, y + dy) >= 0.0f) {
            sum += face.at(x + dx, y + dy);
            ++count;
          }
        }
        if (count > 0) {
          next.at(x, y) = sum / static_cast<float>(count);
        } else {
          missing = true;
        }
      }
    }
    face = std::move(next);
    if (!missing) return;
  }
  for (float& v : face.values) v = std::max(v, 0.0f);
}

}  // namespace

Cubemap radius_cubemap(const CrownMesh& mesh, const Eigen::Vector3f& centre, int size) {
  Cubemap cube(size, 1);
  for (Raster& f : cube.faces) f.values.assign(f.values.size(), -1.0f);
  std::vector<bool> used(mesh.positions.size(), false);
  for (std::size_t t = 0; t < mesh.crown_triangles; ++t) {
    for (std::uint32_t v : mesh.triangles[t]) used[v] = true;
  }
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Eigen::Vector3f d = mesh.positions[v] - centre;
    if (!used[v] || d.squaredNorm() == 0.0f) continue;
    const CubeTexel t = direction_texel(d, size);
    float& r = cube.faces[static_cast<std::size_t>(t.face)].at(t.x, t.y);
    r = std::max(r, d.norm());
  }
  for (Raster& f : cube.faces) fill_holes(f);
  return cube;
}

Cubemap height_cubemap(const Cubemap& color, int levels) {
  Cubemap out(color.size, 1);
  Mask all(color.size, color.size);
  all.inside.assign(all.inside.size(), 1);
  ReliefOptions options;
  options.levels = levels;
  for (int f = 0; f < kCubeFaces; ++f) {
    out.faces[static_cast<std::size_t>(f)] =
        luminance_heightfield(color.faces[static_cast<std::size_t>(f)], all, options);
  }
  return out;
}

float sample(const Cubemap& cubemap, const Eigen::Vector3f& direction) {
  const CubeTexel t = direction_texel(direction, cubemap.size);
  return cubemap.faces[static_cast<std::size_t>(t.face)].at(t.x, t.y);
}

}  // namespace fspm::crown
