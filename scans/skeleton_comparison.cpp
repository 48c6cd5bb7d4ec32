#include "scans/skeleton_comparison.hpp"

#include <algorithm>
#include <limits>

#include "fspm/constrained_edit_distance.hpp"
#include "fspm/tree_traversal.hpp"
#include "scans/segment_distance.hpp"

namespace fspm::scans {
namespace {

std::vector<Eigen::Vector3d> branch_points(const TreeGraph& t) {
  std::vector<Eigen::Vector3d> out;
  for (NodeId u = 0; u < t.size(); ++u) {
    if (t.child_count(u) >= 2) out.push_back(t.end(u));
  }
  return out;
}

NodeId nearest_segment(const TreeGraph& t, const Eigen::Vector3d& p, double& distance) {
  NodeId best = kNoNode;
  distance = std::numeric_limits<double>::infinity();
  for (NodeId u = 0; u < t.size(); ++u) {
    const double d = segment_distance(p, p, t.start(u), t.end(u));
    if (d < distance) distance = d, best = u;
  }
  return best;
}

double mean_branch_point_error(const TreeGraph& truth, const TreeGraph& recovered) {
  const std::vector<Eigen::Vector3d> a = branch_points(truth), b = branch_points(recovered);
  if (a.empty() || b.empty()) return a.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (const Eigen::Vector3d& p : a) {
    double best = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector3d& q : b) best = std::min(best, (p - q).norm());
    sum += best;
  }
  return sum / static_cast<double>(a.size());
}

// The point half-way along the axis that starts at u (u and the children of its order after it).
Eigen::Vector3d half_way(const TreeGraph& t, NodeId u) {
  std::vector<NodeId> axis{u};
  for (bool more = true; more;) {
    more = false;
    for (NodeId c : t.children(axis.back())) {
      if (t.order(c) == t.order(u)) {
        axis.push_back(c), more = true;
        break;
      }
    }
  }
  double total = 0.0;
  for (NodeId a : axis) total += (t.end(a) - t.start(a)).norm();
  double left = 0.5 * total;
  for (NodeId a : axis) {
    const double len = (t.end(a) - t.start(a)).norm();
    if (left <= len && len > 0.0) return t.start(a) + left / len * (t.end(a) - t.start(a));
    left -= len;
  }
  return t.end(axis.back());
}

bool descends_from(const TreeGraph& t, NodeId w, NodeId v) {
  for (NodeId a = t.parent(w); a != kNoNode; a = t.parent(a)) {
    if (a == v) return true;
  }
  return false;
}

bool recovered_branch(const TreeGraph& truth, NodeId u, const TreeGraph& r, double tol) {
  const Eigen::Vector3d fork = truth.start(u), half = half_way(truth, u);
  for (NodeId v = 0; v < r.size(); ++v) {
    if (r.child_count(v) < 2 || (r.end(v) - fork).norm() > tol) continue;
    for (NodeId w = 0; w < r.size(); ++w) {
      if (segment_distance(half, half, r.start(w), r.end(w)) <= tol && descends_from(r, w, v)) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace

BranchRecovery branch_recovery(const TreeGraph& truth, const TreeGraph& recovered,
                               double min_diameter_m, double tolerance_m) {
  BranchRecovery b;
  for (NodeId u = 0; u < truth.size(); ++u) {
    const NodeId p = truth.parent(u);
    if (p == kNoNode || truth.order(u) <= truth.order(p) ||
        truth.kind(u) != OrganKind::kInternode || 2.0 * truth.radius(u) < min_diameter_m) {
      continue;
    }
    ++b.branches;
    if (recovered_branch(truth, u, recovered, tolerance_m)) ++b.recovered;
  }
  return b;
}

TreeGraph branching_structure(const TreeGraph& t) {
  TreeGraph out;
  if (t.empty()) return out;
  std::vector<NodeId> chain_of_tip(t.size(), kNoNode);  // last node of a chain -> its new id
  for (const std::vector<NodeId>& chain : chains(t)) {
    NodeData d;
    d.start = t.start(chain.front());
    d.end = t.end(chain.back());
    d.length = 0.0;
    for (NodeId u : chain) d.length += t.length(u);
    d.direction = (d.end - d.start).normalized();
    d.radius = t.radius(chain.front());
    const NodeId p = t.parent(chain.front());
    chain_of_tip[chain.back()] = out.add_node(p == kNoNode ? kNoNode : chain_of_tip[p], d);
  }
  return out;
}

TreeGraph main_skeleton(const TreeGraph& t, double min_radius_m) {
  TreeGraph out;
  const std::vector<NodeId> nodes = main_skeleton_nodes(t, min_radius_m);
  std::vector<NodeId> map(t.size(), kNoNode);
  for (NodeId u : nodes) {
    const NodeId p = t.parent(u);
    map[u] = out.add_node(p == kNoNode ? kNoNode : map[p], t.data(u));
  }
  return out;
}

SkeletonComparison compare_skeletons(const TreeGraph& truth, const TreeGraph& recovered) {
  SkeletonComparison c;
  const TreeGraph a = branching_structure(truth), b = branching_structure(recovered);
  c.true_branches = a.size();
  c.recovered_branches = b.size();
  c.edit_distance = constrained_edit_distance(a, b).distance;
  c.branch_point_error_m = mean_branch_point_error(truth, recovered);
  double position = 0.0, diameter = 0.0;
  for (NodeId u = 0; u < recovered.size(); ++u) {
    double d = 0.0;
    const NodeId v = nearest_segment(truth, recovered.end(u), d);
    position += d;
    diameter += std::abs(recovered.radius(u) - truth.radius(v)) / truth.radius(v);
  }
  const double n = std::max<double>(1.0, static_cast<double>(recovered.size()));
  c.position_error_m = position / n;
  c.diameter_error = diameter / n;
  return c;
}

}  // namespace fspm::scans
