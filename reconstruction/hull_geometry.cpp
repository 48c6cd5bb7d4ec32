#include "reconstruction/hull_geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fspm::reconstruction {

std::vector<double> ray_hull_crossings(const scans::ClusterHull& hull,
                                       const Eigen::Vector3d& origin,
                                       const Eigen::Vector3d& direction) {
  constexpr double kParallel = 1e-14;
  std::vector<double> ts;
  for (const auto& tri : hull.triangles) {
    const Eigen::Vector3d& a = hull.vertices[tri[0]];
    const Eigen::Vector3d e1 = hull.vertices[tri[1]] - a;
    const Eigen::Vector3d e2 = hull.vertices[tri[2]] - a;
    const Eigen::Vector3d p = direction.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < kParallel * e1.norm() * e2.norm() * direction.norm()) continue;
    const Eigen::Vector3d s = origin - a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = direction.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    const double t = e2.dot(q) / det;
    if (t > 0.0) ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  return ts;
}

bool inside_hull(const scans::ClusterHull& hull, const Eigen::Vector3d& point) {
  // An irrational-looking direction so that rays through edges and vertices of axis-aligned or
  // symmetric hulls are unlikely.
  const Eigen::Vector3d direction(0.5773502691896258, 0.4472135954999579, 0.6823278038280193);
  return ray_hull_crossings(hull, point, direction).size() % 2 == 1;
}

Eigen::Vector3d hull_centroid(const scans::ClusterHull& hull) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : hull.vertices) sum += v;
  return hull.vertices.empty() ? sum : Eigen::Vector3d(sum / double(hull.vertices.size()));
}

}  // namespace fspm::reconstruction
