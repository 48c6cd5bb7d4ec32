#include "scans/cluster_split.hpp"

#include <Eigen/Geometry>

#include "fspm/error.hpp"

namespace fspm::scans {

double mean_point_distance_m(const PointSet& ps, const PointSkeleton& s, NodeId u) {
  const Eigen::Vector3d a = s.tree.start(u);
  const Eigen::Vector3d b = s.tree.end(u);
  const Eigen::Vector3d axis = b - a;
  const double len = axis.norm();
  double sum = 0.0;
  for (std::uint32_t k = s.first[u]; k < s.first[u + 1]; ++k) {
    const Eigen::Vector3d d = ps.points[s.members[k]] - b;
    sum += len > 0.0 ? d.cross(axis / len).norm() : d.norm();
  }
  const std::uint32_t count = s.first[u + 1] - s.first[u];
  return count > 0 ? sum / count : 0.0;
}

ClusterSplit split_clusters(const PointSet& ps, const PointSkeleton& s, double f_s) {
  if (!(f_s > 0.0)) throw ValueError("f_s must be positive");
  const TreeGraph& t = s.tree;
  ClusterSplit out;
  out.main_of.assign(t.size(), kNoNode);
  std::vector<std::uint32_t> cluster_of(t.size(), UINT32_MAX);
  std::vector<std::uint32_t> cluster_at_main(t.size(), UINT32_MAX);  // by full id of p_i
  for (NodeId u = 0; u < t.size(); ++u) {
    const NodeId p = t.parent(u);
    const double diameter = 2.0 * t.radius(u);
    const bool confident = mean_point_distance_m(ps, s, u) <= f_s * diameter;  // eq. 3.2
    if (p == kNoNode || (out.main_of[p] != kNoNode && confident)) {
      NodeData d = t.data(u);
      out.main_of[u] = out.main_skeleton.add_node(p == kNoNode ? kNoNode : out.main_of[p], d);
    } else if (out.main_of[p] != kNoNode) {
      if (cluster_at_main[p] == UINT32_MAX) {
        cluster_at_main[p] = static_cast<std::uint32_t>(out.clusters.size());
        out.clusters.push_back({out.main_of[p], {}});
      }
      cluster_of[u] = cluster_at_main[p];
    } else {
      cluster_of[u] = cluster_of[p];
    }
  }
  for (NodeId u = 0; u < t.size(); ++u) {
    if (cluster_of[u] == UINT32_MAX) continue;
    out.clusters[cluster_of[u]].branch_length_m += t.length(u);
    auto& pts = out.clusters[cluster_of[u]].points;
    pts.insert(pts.end(), s.members.begin() + s.first[u], s.members.begin() + s.first[u + 1]);
  }
  return out;
}

}  // namespace fspm::scans
