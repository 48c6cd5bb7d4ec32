#include "scans/synthetic_tree.hpp"

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "scans/allometry.hpp"

namespace fspm::scans {
namespace {

// Adds an axis of `length` from the end of `parent` (the origin for kNoNode) along `dir`;
// returns its node ids, base to tip.
std::vector<NodeId> add_axis(TreeGraph& t, NodeId parent, const Eigen::Vector3d& dir, double length,
                             double internode, std::uint16_t order) {
  const int n = std::max(1, static_cast<int>(std::lround(length / internode)));
  std::vector<NodeId> ids;
  Eigen::Vector3d at = parent == kNoNode ? Eigen::Vector3d::Zero() : t.end(parent);
  for (int k = 0; k < n; ++k) {
    NodeData d;
    d.start = at;
    d.end = at + dir.normalized() * (length / n);
    d.order = order;
    parent = t.add_node(parent, d);
    ids.push_back(parent);
    at = d.end;
  }
  return ids;
}

Eigen::Vector3d heading(double azimuth, double from_vertical) {
  return {std::sin(from_vertical) * std::cos(azimuth), std::sin(from_vertical) * std::sin(azimuth),
          std::cos(from_vertical)};
}

}  // namespace

void SyntheticTreeOptions::validate() const {
  if (!(trunk_length_m > 0) || !(internode_length_m > 0)) {
    throw ValueError("synthetic tree: trunk_length_m and internode_length_m must be positive");
  }
  if (branches < 0 || twigs < 0) {
    throw ValueError("synthetic tree: branches and twigs must not be negative");
  }
}

TreeGraph synthetic_tree(const SyntheticTreeOptions& o) {
  o.validate();
  constexpr double kDeg = std::numbers::pi / 180.0;
  TreeGraph t;
  const std::vector<NodeId> trunk =
      add_axis(t, kNoNode, {0, 0, 1}, o.trunk_length_m, o.internode_length_m, 0);
  for (int b = 0; b < o.branches; ++b) {
    // Evenly over the upper 60 % of the trunk, leaving its last internode as the leader.
    const double f = 0.4 + 0.55 * (b + 0.5) / o.branches;
    const NodeId at = trunk[static_cast<std::size_t>(f * static_cast<double>(trunk.size() - 1))];
    const double az = 137.5 * kDeg * b;
    const std::vector<NodeId> axis =
        add_axis(t, at, heading(az, 50 * kDeg), o.branch_length_m, o.internode_length_m, 1);
    for (int k = 0; k < o.twigs; ++k) {
      const NodeId from = axis[(axis.size() * static_cast<std::size_t>(k + 1)) /
                               static_cast<std::size_t>(o.twigs + 1)];
      const double side = (k % 2 == 0 ? 1.0 : -1.0) * 60 * kDeg;
      add_axis(t, from, heading(az + side, 60 * kDeg), o.twig_length_m, o.internode_length_m, 2);
    }
  }
  set_allometric_radii(t, o.root_diameter_m, o.gamma);
  return t;
}

}  // namespace fspm::scans
