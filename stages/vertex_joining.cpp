#include "stages/vertex_joining.hpp"

#include "stages/point_grid.hpp"

namespace fspm::stages {

JoinedVertices join_vertices(const Eigen::MatrixX3d& positions, double t_dist) {
  const auto n = static_cast<std::uint32_t>(positions.rows());
  std::vector<Eigen::Vector3d> points(n);
  for (std::uint32_t i = 0; i < n; ++i) points[i] = positions.row(i).transpose();
  const PointGrid grid(points, t_dist);
  JoinedVertices out;
  out.node_of.assign(n, UINT32_MAX);
  for (std::uint32_t seed = 0; seed < n; ++seed) {
    if (out.node_of[seed] != UINT32_MAX) continue;
    const auto node = static_cast<std::uint32_t>(out.positions.size());
    std::vector<std::uint32_t> group;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    grid.for_each_near(points[seed], t_dist, [&](std::uint32_t i) {
      if (out.node_of[i] != UINT32_MAX) return;
      out.node_of[i] = node;  // eq. 5.1: d(seed, v_i) <= t_dist
      group.push_back(i);
      sum += points[i];
    });
    out.positions.push_back(sum / static_cast<double>(group.size()));  // eq. 5.2
    out.members.push_back(std::move(group));
  }
  return out;
}

}  // namespace fspm::stages
