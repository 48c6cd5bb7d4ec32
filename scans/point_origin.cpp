#include "scans/point_origin.hpp"

#include <cmath>

namespace fspm::scans {

Eigen::Vector3d point_set_origin(const PointSet& ps) {
  if (ps.points.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d lo = ps.points[0];
  for (const Eigen::Vector3d& p : ps.points) lo = lo.cwiseMin(p);
  return lo.array().floor().matrix();
}

PointSet relative_to(const PointSet& ps, const Eigen::Vector3d& origin) {
  PointSet out;
  out.points.reserve(ps.points.size());
  for (const Eigen::Vector3d& p : ps.points) out.points.push_back(p - origin);
  return out;
}

void translate_tree(TreeGraph& tree, const Eigen::Vector3d& offset) {
  for (NodeId u = 0; u < tree.size(); ++u) {
    const Eigen::Vector3d direction = tree.direction(u);
    const double length = tree.length(u);
    tree.set_segment(u, tree.start(u) + offset, tree.end(u) + offset);
    tree.set_direction(u, direction);
    tree.set_length(u, length);
  }
}

}  // namespace fspm::scans
