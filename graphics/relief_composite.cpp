#include "graphics/relief_composite.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

// A placed crown: world from its frame and back, and its bounding sphere in the world.
struct Placed {
  const ReliefCrown* crown = nullptr;
  Eigen::Matrix4f model, inverse;
  Eigen::Vector3f world_centre;
  float bound = 0.0f;  // of the bounding sphere, crown frame
  float world_bound = 0.0f;
};

std::vector<Placed> placements(const std::vector<ReliefCrown>& crowns) {
  std::vector<Placed> out;
  for (const ReliefCrown& c : crowns) {
    c.validate();
    const float bound = 1.01f * c.max_radius_m();
    for (const Eigen::Matrix4f& m : c.placements) {
      const float scale = std::cbrt(std::abs(m.block<3, 3>(0, 0).determinant()));
      out.push_back(
          {&c, m, m.inverse(), (m * c.centre_m.homogeneous()).head<3>(), bound, scale * bound});
    }
  }
  return out;
}

// The outward normal at crown point q (from the centre, crown frame): the gradient of
// |q| - R(q) by central differences, as the viewer's shader takes it.
Eigen::Vector3f crown_normal(const ReliefCrown& c, const Eigen::Vector3f& q, float bound) {
  const float e = bound / 128.0f;
  const auto outside = [&](const Eigen::Vector3f& p) {
    const float r = p.norm();
    return r < 1e-6f * bound ? -1.0f : r - relief_radius_m(c, p);
  };
  Eigen::Vector3f g;
  for (int a = 0; a < 3; ++a) {
    const Eigen::Vector3f step = e * Eigen::Vector3f::Unit(a);
    g[a] = outside(q + step) - outside(q - step);
  }
  return g.squaredNorm() < 1e-20f ? q : g;
}

}  // namespace

std::size_t composite_relief_crowns(const std::vector<ReliefCrown>& crowns,
                                    const PictureCamera& camera, std::span<const float> depth,
                                    Image& image) {
  const int w = image.width, h = image.height;
  if (depth.size() != static_cast<std::size_t>(w) * static_cast<std::size_t>(h)) {
    throw ValueError("relief crowns: expected one depth per pixel of the picture");
  }
  const std::vector<Placed> placed = placements(crowns);
  const Eigen::Matrix4d inverse = camera.view_projection.inverse();
  const auto unproject = [&](double x, double y, double z) {
    const Eigen::Vector4d p = inverse * Eigen::Vector4d(x, y, z, 1.0);
    return Eigen::Vector3f((p.head<3>() / p.w()).cast<float>());
  };
  std::size_t written = 0;
  for (int row = 0; row < h; ++row) {
    const int gl_row = h - 1 - row;
    const double ny = 2.0 * (gl_row + 0.5) / h - 1.0;
    for (int x = 0; x < w; ++x) {
      const double nx = 2.0 * (x + 0.5) / w - 1.0;
      const Eigen::Vector3f near = unproject(nx, ny, -1.0), far = unproject(nx, ny, 1.0);
      const Eigen::Vector3f dir = (far - near).normalized();
      float best = depth[static_cast<std::size_t>(gl_row) * w + x];
      Eigen::Vector3f colour;
      bool hit = false;
      for (const Placed& p : placed) {
        // The bounding sphere first: most rays miss most crowns.
        const Eigen::Vector3f oc = near - p.world_centre;
        const float b = oc.dot(dir);
        if (b * b - (oc.squaredNorm() - p.world_bound * p.world_bound) < 0.0f) continue;
        const Eigen::Vector3f o = (p.inverse * near.homogeneous()).head<3>();
        const Eigen::Vector3f d = ((p.inverse * far.homogeneous()).head<3>() - o).normalized();
        float t = 0.0f;
        if (!relief_ray_hit(*p.crown, p.bound, o, d, t)) continue;
        const Eigen::Vector3f local = o + t * d;
        const Eigen::Vector3f world = (p.model * local.homogeneous()).head<3>();
        const Eigen::Vector4d clip = camera.view_projection * world.cast<double>().homogeneous();
        const float z = static_cast<float>(0.5 * (clip.z() / clip.w() + 1.0));
        if (!(z < best)) continue;
        best = z;
        hit = true;
        const ReliefCrown& c = *p.crown;
        const Eigen::Vector3f q = local - c.centre_m;
        const Eigen::Vector3f n =
            (p.model.block<3, 3>(0, 0) * crown_normal(c, q, p.bound)).normalized();
        colour = relief_shade(relief_color(c, q), q, relief_radius_m(c, q), p.bound, n, camera.sun);
      }
      if (!hit) continue;
      std::uint8_t* px = image.pixel(x, row);
      for (int k = 0; k < 3; ++k)
        px[k] = static_cast<std::uint8_t>(std::lround(255.0f * colour[k]));
      px[3] = 255;
      ++written;
    }
  }
  return written;
}

}  // namespace fspm::graphics
