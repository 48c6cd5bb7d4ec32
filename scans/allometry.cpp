#include "scans/allometry.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "fspm/error.hpp"
#include "scans/circle_fit.hpp"

namespace fspm::scans {

std::vector<double> subtree_lengths_m(const TreeGraph& tree) {
  std::vector<double> l(tree.size(), 0.0);
  for (NodeId u = static_cast<NodeId>(tree.size()); u-- > 0;) {
    l[u] += tree.length(u);
    if (tree.parent(u) != kNoNode) l[tree.parent(u)] += l[u];
  }
  return l;
}

void set_allometric_radii(TreeGraph& tree, double d_root_m, double gamma) {
  if (!(d_root_m > 0.0) || !(gamma >= 0.0)) {
    throw ValueError("eq. 3.1 needs a positive root diameter and a non-negative gamma");
  }
  const std::vector<double> l = subtree_lengths_m(tree);
  if (tree.empty()) return;
  const double total = l[0];
  for (NodeId u = 0; u < tree.size(); ++u) {
    const double ratio = total > 0.0 ? l[u] / total : 1.0;
    tree.set_radius(u, 0.5 * d_root_m * std::pow(ratio, gamma));  // eq. 3.1
  }
}

void set_branch_orders(TreeGraph& tree) {
  const std::vector<double> l = subtree_lengths_m(tree);
  for (NodeId u = 0; u < tree.size(); ++u) {
    NodeId main = kNoNode;
    for (NodeId c : tree.children(u)) {
      if (main == kNoNode || l[c] > l[main]) main = c;
    }
    for (NodeId c : tree.children(u)) {
      tree.set_order(c, static_cast<std::uint16_t>(tree.order(u) + (c == main ? 0 : 1)));
    }
  }
}

double estimate_root_diameter_m(const PointSet& ps, const PointSkeleton& s, double height_m) {
  if (s.tree.empty()) return 0.0;
  double z0 = ps.points[s.members[s.first[0]]].z();
  for (std::uint32_t k = s.first[0]; k < s.first[1]; ++k)
    z0 = std::min(z0, ps.points[s.members[k]].z());
  // The trunk: from the root, follow the order-0 child while it stays below height_m.
  std::vector<std::uint32_t> pts;
  for (NodeId u = 0; u != kNoNode;) {
    for (std::uint32_t k = s.first[u]; k < s.first[u + 1]; ++k) {
      if (ps.points[s.members[k]].z() <= z0 + height_m) pts.push_back(s.members[k]);
    }
    NodeId next = kNoNode;
    for (NodeId c : s.tree.children(u)) {
      if (s.tree.order(c) == s.tree.order(u) && s.tree.end(c).z() <= z0 + height_m) next = c;
    }
    u = next;
  }
  if (pts.size() < 5) return 0.0;
  std::vector<Eigen::Vector2d> xy;
  xy.reserve(pts.size());
  for (std::uint32_t i : pts) xy.push_back(ps.points[i].head<2>());
  const std::optional<Circle> c = fit_circle_kasa(xy);
  return c ? 2.0 * c->radius_m : 0.0;
}

}  // namespace fspm::scans
