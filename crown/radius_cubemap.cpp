#include "crown/radius_cubemap.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
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

// A direction's coordinates on cube face f, as crown/cubemap.cpp's texel_direction lays the faces
// out: (U, V) across the face, W along its axis (the direction meets the face where W > 0, at
// u = U / W, v = V / W).
Eigen::Vector3f face_coordinates(int f, const Eigen::Vector3f& d) {
  switch (f) {
    case 0:
      return {d.x(), -d.z(), -d.y()};
    case 1:
      return {d.y(), -d.z(), d.x()};
    case 2:
      return {-d.x(), -d.z(), d.y()};
    case 3:
      return {-d.y(), -d.z(), -d.x()};
    case 4:
      return {d.x(), -d.y(), d.z()};
    default:
      return {d.x(), d.y(), -d.z()};
  }
}

// Distance along the unit ray from the origin to triangle (a, b, c), or -1 when it misses
// (Moller and Trumbore 1997).
float ray_triangle(const Eigen::Vector3f& dir, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                   const Eigen::Vector3f& c) {
  const Eigen::Vector3f e1 = b - a, e2 = c - a;
  const Eigen::Vector3f p = dir.cross(e2);
  const float det = e1.dot(p);
  if (std::abs(det) < 1e-12f) return -1.0f;
  const Eigen::Vector3f s = -a;
  const float u = s.dot(p) / det;
  if (u < -1e-6f || u > 1.0f + 1e-6f) return -1.0f;
  const Eigen::Vector3f q = s.cross(e1);
  const float v = dir.dot(q) / det;
  if (v < -1e-6f || u + v > 1.0f + 1e-6f) return -1.0f;
  return e2.dot(q) / det;
}

// Argudo renders the crown into the cubemap. Here every texel whose direction passes through the
// triangle (a, b, c) (relative to the centre) takes the distance to it, the largest kept: the
// crown's outer surface. A triangle is drawn on each face it lies wholly in front of; one that
// crosses a face's plane (a few at the cube's edges) is left to the vertex splat.
void draw_triangle(const Eigen::Vector3f& a, const Eigen::Vector3f& b, const Eigen::Vector3f& c,
                   Cubemap& cube) {
  const int n = cube.size;
  for (int f = 0; f < kCubeFaces; ++f) {
    const Eigen::Vector3f fa = face_coordinates(f, a), fb = face_coordinates(f, b),
                          fc = face_coordinates(f, c);
    if (fa.z() <= 0.0f || fb.z() <= 0.0f || fc.z() <= 0.0f) continue;
    const float u[3] = {fa.x() / fa.z(), fb.x() / fb.z(), fc.x() / fc.z()};
    const float v[3] = {fa.y() / fa.z(), fb.y() / fb.z(), fc.y() / fc.z()};
    auto texel = [n](float t) {
      return std::clamp(static_cast<int>(std::floor(0.5f * (t + 1.0f) * n)), 0, n - 1);
    };
    const float u_lo = std::min({u[0], u[1], u[2]}), u_hi = std::max({u[0], u[1], u[2]});
    const float v_lo = std::min({v[0], v[1], v[2]}), v_hi = std::max({v[0], v[1], v[2]});
    if (u_hi < -1.0f || u_lo > 1.0f || v_hi < -1.0f || v_lo > 1.0f) continue;
    Raster& face = cube.faces[static_cast<std::size_t>(f)];
    for (int y = texel(v_lo); y <= texel(v_hi); ++y) {
      for (int x = texel(u_lo); x <= texel(u_hi); ++x) {
        const float t = ray_triangle(texel_direction(f, x, y, n), a, b, c);
        if (t > 0.0f) face.at(x, y) = std::max(face.at(x, y), t);
      }
    }
  }
}

}  // namespace

Cubemap radius_cubemap(const CrownMesh& mesh, const Eigen::Vector3f& centre, int size) {
  Cubemap cube(size, 1);
  for (Raster& f : cube.faces) f.values.assign(f.values.size(), -1.0f);
  for (std::size_t t = 0; t < mesh.crown_triangles; ++t) {
    const auto& tri = mesh.triangles[t];
    draw_triangle(mesh.positions[tri[0]] - centre, mesh.positions[tri[1]] - centre,
                  mesh.positions[tri[2]] - centre, cube);
  }
  // Every vertex in its texel too: the triangles across a face's plane, and texels between
  // triangles' footprints.
  for (std::size_t t = 0; t < mesh.crown_triangles; ++t) {
    for (std::uint32_t v : mesh.triangles[t]) {
      const Eigen::Vector3f d = mesh.positions[v] - centre;
      if (d.squaredNorm() == 0.0f) continue;
      const CubeTexel texel = direction_texel(d, size);
      float& r = cube.faces[static_cast<std::size_t>(texel.face)].at(texel.x, texel.y);
      r = std::max(r, d.norm());
    }
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
