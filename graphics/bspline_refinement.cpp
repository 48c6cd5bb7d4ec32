// Uniform cubic B-spline refinement of chains (Pirk 2013, eq. 6.6-6.7).
#include "graphics/bspline_refinement.hpp"

#include <Eigen/Core>

#include "fspm/error.hpp"

namespace fspm::graphics {

Eigen::Vector3d cubic_bspline(const Eigen::Vector3d& p_before, const Eigen::Vector3d& p0,
                              const Eigen::Vector3d& p1, const Eigen::Vector3d& p_after, double t) {
  Eigen::Matrix4d basis;
  basis << -1, 3, -3, 1,  //
      3, -6, 3, 0,        //
      -3, 0, 3, 0,        //
      1, 4, 1, 0;
  const Eigen::RowVector4d powers(t * t * t, t * t, t, 1.0);
  const Eigen::RowVector4d w = powers * basis / 6.0;
  return w(0) * p_before + w(1) * p0 + w(2) * p1 + w(3) * p_after;
}

std::vector<Eigen::Vector3d> refine_chain(const std::vector<Eigen::Vector3d>& points,
                                          int subdivisions) {
  if (subdivisions < 1) throw ValueError("B-spline refinement needs at least one subdivision");
  const std::size_t n = points.size();
  if (n < 2) return points;
  // Phantom points beyond the ends, the end points reflected through their neighbours
  // (P_{-1} = 2 P_0 - P_1, P_n = 2 P_{n-1} - P_{n-2}): then S_0(0) = P_0 and S_{n-2}(1) = P_{n-1},
  // so a refined chain still starts and ends where it meets the next ones.
  const long last_index = static_cast<long>(n) - 1;
  auto at = [&](long i) -> Eigen::Vector3d {
    if (i < 0) return 2.0 * points[0] - points[1];
    if (i > last_index) return 2.0 * points[n - 1] - points[n - 2];
    return points[static_cast<std::size_t>(i)];
  };
  std::vector<Eigen::Vector3d> out;
  out.reserve((n - 1) * static_cast<std::size_t>(subdivisions) + 1);
  for (long i = 0; i + 1 < static_cast<long>(n); ++i) {
    for (int k = 0; k < subdivisions; ++k) {
      out.push_back(cubic_bspline(at(i - 1), at(i), at(i + 1), at(i + 2),
                                  static_cast<double>(k) / subdivisions));
    }
  }
  const long last = static_cast<long>(n) - 2;
  out.push_back(cubic_bspline(at(last - 1), at(last), at(last + 1), at(last + 2), 1.0));
  return out;
}

}  // namespace fspm::graphics
