#include "environment/occluders.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fspm/error.hpp"

namespace fspm::environment {

double cluster_translucency(double radius_m, double gamma0) { return std::pow(gamma0, radius_m); }

namespace {

void check_translucency(double translucency) {
  if (!(translucency >= 0.0 && translucency <= 1.0)) {
    throw ValueError("translucency: expected a value in [0, 1], got " +
                     std::to_string(translucency));
  }
}

}  // namespace

void Sphere::validate() const {
  const Sphere& sphere = *this;
  if (!sphere.center.allFinite()) throw ValueError("sphere: expected a finite centre");
  if (!(sphere.radius_m > 0.0) || !std::isfinite(sphere.radius_m)) {
    throw ValueError("radius: expected a finite value > 0");
  }
  check_translucency(sphere.translucency);
}

void Box::validate() const {
  const Box& box = *this;
  if (!box.center.allFinite()) throw ValueError("box: expected a finite centre");
  if (!box.half_extent.allFinite() || !(box.half_extent.array() > 0.0).all()) {
    throw ValueError(
        "box: expected a finite size > 0 along every axis (min < max; a wall's distinct ends, "
        "height > 0 and thickness > 0)");
  }
  const Eigen::Matrix3d gram = box.rotation.transpose() * box.rotation;
  if (!box.rotation.allFinite() || !gram.isIdentity(1e-9)) {
    throw ValueError("box: expected a rotation (orthonormal columns)");
  }
  check_translucency(box.translucency);
}

void Ground::validate() const {
  const Ground& ground = *this;
  if (!std::isfinite(ground.height_m)) throw ValueError("ground: expected a finite height");
  check_translucency(ground.translucency);
}

Box Box::from_min_max(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  Box b;
  b.center = 0.5 * (min + max);
  b.half_extent = 0.5 * (max - min);
  return b;
}

Box Box::wall(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double base_z_m,
              double height_m, double thickness_m) {
  Box b;
  const Eigen::Vector2d along = to - from;
  const double length = along.norm();
  const Eigen::Vector2d u = length > 0 ? Eigen::Vector2d(along / length) : Eigen::Vector2d(1, 0);
  b.rotation.col(0) = Eigen::Vector3d(u.x(), u.y(), 0);
  b.rotation.col(1) = Eigen::Vector3d(-u.y(), u.x(), 0);
  b.rotation.col(2) = Eigen::Vector3d::UnitZ();
  const Eigen::Vector2d mid = 0.5 * (from + to);
  b.center = Eigen::Vector3d(mid.x(), mid.y(), base_z_m + 0.5 * height_m);
  b.half_extent = Eigen::Vector3d(0.5 * length, 0.5 * thickness_m, 0.5 * height_m);
  return b;
}

double Box::top_z() const {
  double h = 0.0;
  for (int j = 0; j < 3; ++j) h += std::abs(rotation(2, j)) * half_extent[j];
  return center.z() + h;
}

bool Box::contains(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d local = to_local(p);
  return (local.cwiseAbs().array() <= half_extent.array()).all();
}

double Box::ray_entry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const {
  return ray_entry_local(to_local(origin), local_direction(dir));
}

Eigen::Vector3d Box::to_local(const Eigen::Vector3d& p) const {
  return rotation.transpose() * (p - center);
}

Eigen::Vector3d Box::local_direction(const Eigen::Vector3d& dir) const {
  return rotation.transpose() * dir;
}

double Box::ray_entry_local(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
  // Slab test in the box frame.
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-300) {
      if (std::abs(o[i]) > half_extent[i]) return -1.0;
      continue;
    }
    const double inv = 1.0 / d[i];
    double a = (-half_extent[i] - o[i]) * inv;
    double b = (half_extent[i] - o[i]) * inv;
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
    if (t0 > t1) return -1.0;
  }
  return t0;
}

BoxRayDirections::BoxRayDirections(std::span<const Eigen::Vector3d> local_dirs) {
  for (int a = 0; a < 3; ++a) {
    inv_[a].resize(local_dirs.size());
    parallel_[a].resize(local_dirs.size());
    for (std::size_t i = 0; i < local_dirs.size(); ++i) {
      const double d = local_dirs[i][a];
      // The threshold and the division of Box::ray_entry_local.
      parallel_[a][i] = std::abs(d) < 1e-300 ? 1 : 0;
      inv_[a][i] = parallel_[a][i] ? 0.0 : 1.0 / d;
    }
  }
}

void BoxRayDirections::hits(const Box& box, const Eigen::Vector3d& local_origin,
                            std::span<std::uint8_t> hit) const {
  // Box::ray_entry_local's slab test without its early exits: the entry distance only grows and
  // the exit distance only shrinks from axis to axis, so the ray misses after some axis exactly
  // when it misses after the last one.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::size_t n = size();
  for (std::size_t i = 0; i < n; ++i) {
    double t0 = 0.0;
    double t1 = kInf;
    bool outside = false;
    for (int a = 0; a < 3; ++a) {
      const double h = box.half_extent[a], o = local_origin[a], inv = inv_[a][i];
      const double x = (-h - o) * inv;
      const double y = (h - o) * inv;
      const bool par = parallel_[a][i] != 0;
      outside = outside || (par && std::abs(o) > h);
      t0 = par ? t0 : std::max(t0, std::min(x, y));
      t1 = par ? t1 : std::min(t1, std::max(x, y));
    }
    hit[i] = (!outside && t0 <= t1) ? 1 : 0;
  }
}

void TriangleMesh::update_bounds() {
  if (vertices.empty()) return;
  Eigen::Vector3d lo = vertices.front(), hi = vertices.front();
  for (const auto& v : vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  center = 0.5 * (lo + hi);
  bounding_radius_m = 0.0;
  for (const auto& v : vertices)
    bounding_radius_m = std::max(bounding_radius_m, (v - center).norm());
}

int TriangleMesh::crossings(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                            double max_t) const {
  // Moeller-Trumbore.
  int count = 0;
  for (const auto& tri : triangles) {
    const Eigen::Vector3d& a = vertices[tri[0]];
    const Eigen::Vector3d e1 = vertices[tri[1]] - a;
    const Eigen::Vector3d e2 = vertices[tri[2]] - a;
    const Eigen::Vector3d p = dir.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-14) continue;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = origin - a;
    const double u = s.dot(p) * inv;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = dir.dot(q) * inv;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = e2.dot(q) * inv;
    if (t > 0.0 && t <= max_t) ++count;
  }
  return count;
}

bool ray_hits_sphere(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                     const Eigen::Vector3d& center, double radius, double max_t) {
  const Eigen::Vector3d oc = center - origin;
  const double c = oc.squaredNorm() - radius * radius;
  if (c < 0.0) return true;  // origin inside
  const double b = oc.dot(dir);
  if (b <= 0.0) return false;
  const double disc = b * b - c;
  if (disc < 0.0) return false;
  return b - std::sqrt(disc) <= max_t;
}

}  // namespace fspm::environment
