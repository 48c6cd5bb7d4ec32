#include "io/obstacle_crop.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace fspm::io {
namespace {

constexpr double kUnbounded = 1e12;  // half height of the region: beyond any scene coordinate

// The box cut along its axes to the projection of the region on them, or nothing when they
// do not overlap.
std::optional<environment::Box> crop_box(const environment::Box& box, const Eigen::Vector3d& c,
                                         const Eigen::Vector3d& e) {
  environment::Box out = box;
  Eigen::Vector3d lo_local, hi_local;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d axis = box.rotation.col(i).normalized();
    const double mid = axis.dot(c - box.center);
    const double half = axis.cwiseAbs().dot(e);  // extent of the region along the axis
    lo_local[i] = std::max(-box.half_extent[i], mid - half);
    hi_local[i] = std::min(box.half_extent[i], mid + half);
    if (lo_local[i] > hi_local[i]) return std::nullopt;
  }
  out.center = box.center + box.rotation * (0.5 * (lo_local + hi_local));
  out.half_extent = 0.5 * (hi_local - lo_local);
  return out;
}

bool overlaps(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, const Eigen::Vector2d& rlo,
              const Eigen::Vector2d& rhi) {
  return lo.x() <= rhi.x() && hi.x() >= rlo.x() && lo.y() <= rhi.y() && hi.y() >= rlo.y();
}

}  // namespace

void obstacle_region(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                     Eigen::Vector2d& region_lo, Eigen::Vector2d& region_hi) {
  const Eigen::Vector3d size = (hi - lo).cwiseMax(0.0);
  const double margin = std::max({size.x(), size.y(), 0.5 * size.z(), 1.0});
  region_lo = lo.head<2>() - Eigen::Vector2d::Constant(margin);
  region_hi = hi.head<2>() + Eigen::Vector2d::Constant(margin);
}

environment::Scene obstacles_near(const environment::Scene& scene, const Eigen::Vector2d& region_lo,
                                  const Eigen::Vector2d& region_hi) {
  const Eigen::Vector2d mid = 0.5 * (region_lo + region_hi);
  const Eigen::Vector3d c(mid.x(), mid.y(), 0.0);
  const Eigen::Vector2d half = 0.5 * (region_hi - region_lo);
  const Eigen::Vector3d e(half.x(), half.y(), kUnbounded);
  environment::Scene out;
  for (const auto& box : scene.boxes) {
    if (auto cropped = crop_box(box, c, e)) out.boxes.push_back(*cropped);
  }
  for (const auto& sphere : scene.spheres) {
    const Eigen::Vector3d r = Eigen::Vector3d::Constant(sphere.radius_m);
    if (overlaps(sphere.center - r, sphere.center + r, region_lo, region_hi)) {
      out.spheres.push_back(sphere);
    }
  }
  for (const auto& mesh : scene.meshes) {
    if (mesh.vertices.empty()) continue;
    Eigen::Vector3d lo = mesh.vertices.front(), hi = lo;
    for (const auto& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    if (overlaps(lo, hi, region_lo, region_hi)) out.meshes.push_back(mesh);
  }
  return out;
}

}  // namespace fspm::io
