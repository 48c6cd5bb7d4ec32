#include "scans/cluster_split.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "fspm/error.hpp"
#include "scans/allometry.hpp"
#include "scans/tip_pruning.hpp"

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

namespace {

// The child of each node that continues its axis: of the children carrying at least half the
// largest sibling's subtree length, the one whose segment turns least from the parent's. A branch
// is followed to its own tip rather than into a twig a little longer than its remaining part;
// short false forks (a split ring of points) are too small to compete.
std::vector<std::uint8_t> continues_axis(const TreeGraph& t, const std::vector<double>& l) {
  std::vector<std::uint8_t> out(t.size(), 0);
  for (NodeId u = 0; u < t.size(); ++u) {
    double largest = 0.0;
    for (NodeId c : t.children(u)) largest = std::max(largest, l[c]);
    NodeId best = kNoNode;
    double best_cos = -2.0;
    for (NodeId c : t.children(u)) {
      if (l[c] < 0.5 * largest) continue;
      const double cos =
          t.length(u) > 0.0 && t.length(c) > 0.0
              ? (t.end(u) - t.start(u)).normalized().dot((t.end(c) - t.start(c)).normalized())
              : (l[c] == largest ? 1.0 : 0.0);
      if (cos > best_cos) best_cos = cos, best = c;
    }
    if (best != kNoNode) out[best] = 1;
  }
  return out;
}

// l(u) of eq. 3.1 without the short side tips: the spurs that split rings of points, leaf tufts
// and noise leave on the skeleton add a length that depends on the scan, not on the tree, and
// would lower every branch's share of l(root).
std::vector<double> branch_lengths_m(const TreeGraph& t, double spur_length_m) {
  const std::vector<std::uint8_t> spur = short_tip_nodes(t, spur_length_m);
  std::vector<double> l(t.size(), 0.0);
  for (NodeId u = static_cast<NodeId>(t.size()); u-- > 0;) {
    if (spur[u] == 0) l[u] += t.length(u);
    if (t.parent(u) != kNoNode) l[t.parent(u)] += l[u];
  }
  return l;
}

// The longest path from the start of each node's segment down to a tip of its subtree.
std::vector<double> reach_lengths_m(const TreeGraph& t) {
  std::vector<double> reach(t.size(), 0.0);
  for (NodeId u = static_cast<NodeId>(t.size()); u-- > 0;) {
    reach[u] += t.length(u);
    const NodeId p = t.parent(u);
    if (p != kNoNode) reach[p] = std::max(reach[p], reach[u]);
  }
  return reach;
}

// The nodes kept whatever eq. 3.2 says (none for Pirk's rule): those continuing their parent's
// axis, and the first nodes of limbs carrying main_branch_share of the skeleton's length or
// reaching main_branch_reach of its longest path.
std::vector<std::uint8_t> main_axis_nodes(const TreeGraph& t, const SplitOptions& o) {
  std::vector<std::uint8_t> out(t.size(), 0);
  if (!o.follow_main_axes || t.empty()) return out;
  const std::vector<double> l =
      o.spur_length_m > 0.0 ? branch_lengths_m(t, o.spur_length_m) : subtree_lengths_m(t);
  const std::vector<std::uint8_t> axis = continues_axis(t, l);
  const std::vector<double> reach = reach_lengths_m(t);
  for (NodeId u = 0; u < t.size(); ++u) {
    const bool limb = l[u] >= o.main_branch_share * l[0] ||
                      (o.main_branch_reach > 0.0 && reach[u] >= o.main_branch_reach * reach[0]);
    out[u] = axis[u] != 0 || limb ? 1 : 0;
  }
  return out;
}

}  // namespace

void SplitOptions::validate() const {
  if (!(f_s > 0.0)) throw ValueError("cluster split: f_s must be positive");
  if (!(main_branch_share >= 0.0)) {
    throw ValueError("cluster split: main_branch_share must not be negative");
  }
  if (!(main_branch_reach >= 0.0)) {
    throw ValueError("cluster split: main_branch_reach must not be negative");
  }
}

ClusterSplit split_clusters(const PointSet& ps, const PointSkeleton& s, const SplitOptions& o) {
  o.validate();
  const TreeGraph& t = s.tree;
  const std::vector<std::uint8_t> main_axis = main_axis_nodes(t, o);
  ClusterSplit out;
  out.main_of.assign(t.size(), kNoNode);
  std::vector<std::uint32_t> cluster_of(t.size(), UINT32_MAX), cluster_at_main;
  cluster_at_main.assign(t.size(), UINT32_MAX);  // by full id of p_i
  for (NodeId u = 0; u < t.size(); ++u) {
    const NodeId p = t.parent(u);
    const double diameter = 2.0 * t.radius(u);
    const bool confident = mean_point_distance_m(ps, s, u) <= o.f_s * diameter;  // eq. 3.2
    if (p == kNoNode || (out.main_of[p] != kNoNode && (confident || main_axis[u] != 0))) {
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
