// Cascaded shadow maps: split distances (Zhang et al. 2006) and each slice's stable orthographic
// view from the sun (Valient 2007).
#include "graphics/shadow_cascades.hpp"

#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {

std::vector<double> cascade_splits(double near_m, double far_m, int count, double lambda) {
  if (!(near_m > 0.0) || !(far_m > near_m)) {
    throw ValueError("cascade splits: expected 0 < near < far, got near " + std::to_string(near_m) +
                     ", far " + std::to_string(far_m));
  }
  if (count < 1) throw ValueError("cascade splits: expected at least one cascade");
  if (!(lambda >= 0.0 && lambda <= 1.0)) {
    throw ValueError("cascade splits: expected lambda in [0, 1], got " + std::to_string(lambda));
  }
  std::vector<double> splits(static_cast<std::size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const double s = static_cast<double>(i) / count;
    const double logarithmic = near_m * std::pow(far_m / near_m, s);
    const double uniform = near_m + (far_m - near_m) * s;
    splits[i] = lambda * logarithmic + (1.0 - lambda) * uniform;  // Zhang et al. 2006, eq. 4
  }
  splits.front() = near_m;  // exact ends, whatever pow rounds to
  splits.back() = far_m;
  return splits;
}

std::vector<Eigen::Vector3d> frustum_slice_corners(const CascadeCamera& camera, double near_m,
                                                   double far_m) {
  const Eigen::Vector3d f = camera.forward.normalized();
  const Eigen::Vector3d right = f.cross(camera.up).normalized();
  const Eigen::Vector3d up = right.cross(f);
  const double tan_half = std::tan(0.5 * camera.vertical_fov_rad);
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(8);
  for (const double d : {near_m, far_m}) {
    const double h = d * tan_half, w = h * camera.aspect;
    for (const int sx : {-1, 1}) {
      for (const int sy : {-1, 1})
        corners.push_back(camera.eye + d * f + sx * w * right + sy * h * up);
    }
  }
  return corners;
}

Eigen::Matrix3d sun_axes(const Eigen::Vector3d& sun) {
  const Eigen::Vector3d z = sun.normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z);
  if (x.norm() < 1e-9) x = Eigen::Vector3d::UnitX();  // the sun along +-y
  x.normalize();
  Eigen::Matrix3d axes;
  axes.col(0) = x;
  axes.col(1) = z.cross(x);
  axes.col(2) = z;
  return axes;
}

namespace {

// Light space (axes^T p) to the map's clip space: x, y from the square of half-width r around
// `center_xy`, depth from `depth_near_m` (-1) down to `depth_far_m` (+1).
Eigen::Matrix4d light_matrix(const Eigen::Matrix3d& axes, const ShadowCascade& c) {
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.topLeftCorner<3, 3>() = axes.transpose();
  Eigen::Matrix4d ortho = Eigen::Matrix4d::Identity();
  const double r = c.half_width_m, range = c.depth_near_m - c.depth_far_m;
  ortho(0, 0) = 1.0 / r;
  ortho(0, 3) = -c.center_xy.x() / r;
  ortho(1, 1) = 1.0 / r;
  ortho(1, 3) = -c.center_xy.y() / r;
  ortho(2, 2) = -2.0 / range;
  ortho(2, 3) = 2.0 * c.depth_near_m / range - 1.0;
  return ortho * view;
}

// One slice's cascade: the bounding sphere of its corners, its centre moved to whole texels.
ShadowCascade fit_cascade(const std::vector<Eigen::Vector3d>& corners, const Eigen::Matrix3d& axes,
                          double scene_depth_near_m, double scene_depth_far_m, int resolution) {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : corners) center += p;
  center /= static_cast<double>(corners.size());
  double radius = 0.0;
  for (const Eigen::Vector3d& p : corners) radius = std::max(radius, (p - center).norm());
  ShadowCascade c;
  c.radius_m = radius;
  // w = r + kCascadeGuardTexels * (2 w / resolution).
  c.half_width_m = radius / (1.0 - 2.0 * kCascadeGuardTexels / resolution);
  c.texel_m = 2.0 * c.half_width_m / resolution;
  const Eigen::Vector3d local = axes.transpose() * center;
  // Whole texels (Valient 2007): the map moves in texel steps, so a texel always covers the same
  // patch of the world and shadow edges do not shimmer as the camera moves.
  c.center_xy = Eigen::Vector2d(std::floor(local.x() / c.texel_m) * c.texel_m,
                                std::floor(local.y() / c.texel_m) * c.texel_m);
  c.depth_near_m = scene_depth_near_m;
  c.depth_far_m = std::max(scene_depth_far_m, local.z() - radius);
  if (c.depth_far_m >= c.depth_near_m) c.depth_far_m = c.depth_near_m - c.texel_m;
  c.light_view_projection = light_matrix(axes, c);
  return c;
}

}  // namespace

std::vector<ShadowCascade> fit_shadow_cascades(const CascadeCamera& camera,
                                               const std::vector<double>& splits,
                                               const Eigen::Vector3d& sun,
                                               const Eigen::AlignedBox3d& scene, int resolution) {
  if (splits.size() < 2) throw ValueError("shadow cascades: expected at least two splits");
  if (resolution < 16) {
    throw ValueError("shadow cascades: expected a resolution of at least 16 texels, got " +
                     std::to_string(resolution));
  }
  if (scene.isEmpty()) throw ValueError("shadow cascades: the scene's box is empty");
  const Eigen::Matrix3d axes = sun_axes(sun);
  double depth_near = -1e300, depth_far = 1e300;
  for (int k = 0; k < 8; ++k) {
    const double d = axes.col(2).dot(scene.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)));
    depth_near = std::max(depth_near, d);
    depth_far = std::min(depth_far, d);
  }
  std::vector<ShadowCascade> cascades;
  for (std::size_t i = 0; i + 1 < splits.size(); ++i) {
    const auto corners = frustum_slice_corners(camera, splits[i], splits[i + 1]);
    ShadowCascade c = fit_cascade(corners, axes, depth_near, depth_far, resolution);
    c.near_m = splits[i];
    c.far_m = splits[i + 1];
    cascades.push_back(c);
  }
  return cascades;
}

bool casts_into(const ShadowCascade& cascade, const Eigen::Matrix3d& axes,
                const Eigen::Vector3d& center, double radius) {
  const Eigen::Vector3d local = axes.transpose() * center;
  const double reach = cascade.half_width_m + radius;
  return std::abs(local.x() - cascade.center_xy.x()) <= reach &&
         std::abs(local.y() - cascade.center_xy.y()) <= reach &&
         local.z() + radius >= cascade.depth_far_m;
}

}  // namespace fspm::graphics
