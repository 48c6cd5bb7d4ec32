#include "graphics/parallel_transport.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fspm::graphics {

Eigen::Matrix3d rotation_about_axis(const Eigen::Vector3d& n, double theta_rad) {
  // Pirk eq. 6.5, written out rather than via Eigen::AngleAxis so the code reads as the equation.
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  const double t = 1.0 - c;
  const double n1 = n.x(), n2 = n.y(), n3 = n.z();
  Eigen::Matrix3d r;
  r << c + n1 * n1 * t, n1 * n2 * t - s * n3, n3 * n1 * t + s * n2,  //
      n1 * n2 * t + s * n3, c + n2 * n2 * t, n3 * n2 * t - s * n1,   //
      n1 * n3 * t - s * n2, n2 * n3 * t + s * n1, c + n3 * n3 * t;
  return r;
}

Eigen::Vector3d transport(const Eigen::Vector3d& v, const Eigen::Vector3d& t_from,
                          const Eigen::Vector3d& t_to) {
  const Eigen::Vector3d b = t_from.cross(t_to);  // eq. 6.2 (tangents are unit)
  const double b_norm = b.norm();
  if (b_norm < 1e-12) {
    if (t_from.dot(t_to) >= 0.0) return v;  // Algorithm 1, line 4
    // Exact reversal: any axis perpendicular to the tangent rotates by pi.
    return rotation_about_axis(any_perpendicular(t_from), M_PI) * v;
  }
  const double theta = std::acos(std::clamp(t_from.dot(t_to), -1.0, 1.0));  // eq. 6.3
  return rotation_about_axis(b / b_norm, theta) * v;                        // eq. 6.4
}

std::vector<Eigen::Vector3d> parallel_transport_normals(std::span<const Eigen::Vector3d> tangents,
                                                        const Eigen::Vector3d& v0) {
  std::vector<Eigen::Vector3d> v(tangents.size());
  if (tangents.empty()) return v;
  Eigen::Vector3d start = v0 - v0.dot(tangents[0]) * tangents[0];
  v[0] = start.norm() > 1e-12 ? start.normalized() : any_perpendicular(tangents[0]);
  for (std::size_t i = 0; i + 1 < tangents.size(); ++i) {
    v[i + 1] = transport(v[i], tangents[i], tangents[i + 1]);
    // Re-orthogonalise against round-off drift over long chains.
    v[i + 1] = (v[i + 1] - v[i + 1].dot(tangents[i + 1]) * tangents[i + 1]).normalized();
  }
  return v;
}

Eigen::Vector3d any_perpendicular(const Eigen::Vector3d& t) {
  // Cross with the world axis least aligned with t.
  Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  if (std::abs(t.y()) < std::abs(t.x()) && std::abs(t.y()) <= std::abs(t.z())) {
    axis = Eigen::Vector3d::UnitY();
  } else if (std::abs(t.z()) < std::abs(t.x())) {
    axis = Eigen::Vector3d::UnitZ();
  }
  return t.cross(axis).normalized();
}

}  // namespace fspm::graphics
