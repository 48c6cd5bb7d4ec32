#include "scan_decoding/hull_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace fspm::scan_decoding {

namespace {

// Moeller-Trumbore: the distance t > 0 at which origin + t direction crosses the triangle, or a
// value <= 0 when it does not.
double crossing(const scans::ClusterHull& hull, const std::array<std::uint32_t, 3>& tri,
                const Eigen::Vector3d& origin, const Eigen::Vector3d& direction) {
  constexpr double kParallel = 1e-14;
  const Eigen::Vector3d& a = hull.vertices[tri[0]];
  const Eigen::Vector3d e1 = hull.vertices[tri[1]] - a;
  const Eigen::Vector3d e2 = hull.vertices[tri[2]] - a;
  const Eigen::Vector3d p = direction.cross(e2);
  const double det = e1.dot(p);
  if (std::abs(det) < kParallel * e1.norm() * e2.norm() * direction.norm()) return 0.0;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot(p) / det;
  if (u < 0.0 || u > 1.0) return 0.0;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = direction.dot(q) / det;
  if (v < 0.0 || u + v > 1.0) return 0.0;
  return e2.dot(q) / det;
}

}  // namespace

std::vector<double> ray_hull_crossings(const scans::ClusterHull& hull,
                                       const Eigen::Vector3d& origin,
                                       const Eigen::Vector3d& direction) {
  std::vector<double> ts;
  for (const auto& tri : hull.triangles) {
    const double t = crossing(hull, tri, origin, direction);
    if (t > 0.0) ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

bool inside_hull(const scans::ClusterHull& hull, const Eigen::Vector3d& point) {
  // An irrational-looking direction so that rays through edges and vertices of axis-aligned or
  // symmetric hulls are unlikely.
  const Eigen::Vector3d direction(0.5773502691896258, 0.4472135954999579, 0.6823278038280193);
  bool inside = false;
  for (const auto& tri : hull.triangles) inside ^= crossing(hull, tri, point, direction) > 0.0;
  return inside;
}

Eigen::Vector3d hull_centroid(const scans::ClusterHull& hull) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : hull.vertices) sum += v;
  return hull.vertices.empty() ? sum : Eigen::Vector3d(sum / double(hull.vertices.size()));
}

}  // namespace fspm::scan_decoding
