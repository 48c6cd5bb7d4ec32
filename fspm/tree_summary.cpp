#include "fspm/tree_summary.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

namespace bg = boost::geometry;
using Point2 = bg::model::d2::point_xy<double>;

// Largest distance between two points of the ground projection: the diameter of its convex hull,
// found by comparing every pair of hull vertices (hulls of trees have few vertices).
// A node that starts where its parent ends adds only its end.
double projection_diameter(const TreeGraph& tree) {
  bg::model::multi_point<Point2> points;
  points.reserve(tree.size() + 1);
  for (NodeId n = 0; n < tree.size(); ++n) {
    const NodeId p = tree.parent(n);
    if (p == kNoNode || tree.start(n) != tree.end(p)) {
      points.emplace_back(tree.start(n).x(), tree.start(n).y());
    }
    points.emplace_back(tree.end(n).x(), tree.end(n).y());
  }
  bg::model::polygon<Point2> hull;
  bg::convex_hull(points, hull);
  const auto& ring = hull.outer();
  double best = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    for (std::size_t j = i + 1; j < ring.size(); ++j) {
      best = std::max(best, bg::distance(ring[i], ring[j]));
    }
  }
  return best;
}

// Crown base: the lowest start of a lateral (order >= 1) node or a leaf. The crown depth is the
// vertical extent from there to the highest point of the tree.
double crown_depth(const TreeGraph& tree) {
  double base = std::numeric_limits<double>::infinity();
  double top = -std::numeric_limits<double>::infinity();
  for (NodeId n = 0; n < tree.size(); ++n) {
    top = std::max({top, tree.start(n).z(), tree.end(n).z()});
    if (tree.order(n) >= 1 || tree.kind(n) == OrganKind::kLeaf) {
      base = std::min(base, std::min(tree.start(n).z(), tree.end(n).z()));
    }
  }
  return std::isfinite(base) ? top - base : 0.0;
}

// Scratch bytes per node: a node's depth, its end in the ground projection and the convex hull's
// sorted copy of it.
constexpr double kSummaryBytesPerNode = sizeof(std::uint32_t) + 2.0 * sizeof(Point2);

}  // namespace

TreeSummary summarize(const TreeGraph& tree) {
  TreeSummary s;
  s.nodes = tree.size();
  if (tree.empty()) return s;
  // The tree is held while its summary is made: both count against the memory limit.
  check_memory(
      static_cast<double>(tree.size()) *
          (TreeGraph::bytes_per_node(tree.attribute_names().size()) + kSummaryBytesPerNode),
      "the summary of a tree of " + std::to_string(tree.size()) + " nodes");
  s.bbox_min = tree.start(0);
  s.bbox_max = tree.start(0);
  std::vector<std::uint32_t> depth(tree.size(), 0);
  double max_z = tree.start(0).z();
  for (NodeId n = 0; n < tree.size(); ++n) {
    switch (tree.kind(n)) {
      case OrganKind::kInternode:
        ++s.internodes;
        s.total_length_m += tree.length(n);
        break;
      case OrganKind::kLeaf:
        ++s.leaves;
        break;
      case OrganKind::kFlower:
        ++s.flowers;
        break;
      case OrganKind::kBud:
        ++s.buds;
        break;
    }
    if (tree.is_tip(n)) ++s.tips;
    s.max_order = std::max<std::size_t>(s.max_order, tree.order(n));
    if (tree.parent(n) != kNoNode) depth[n] = depth[tree.parent(n)] + 1;
    s.max_depth = std::max<std::size_t>(s.max_depth, depth[n]);
    for (const Eigen::Vector3d& p : {tree.start(n), tree.end(n)}) {
      s.bbox_min = s.bbox_min.cwiseMin(p);
      s.bbox_max = s.bbox_max.cwiseMax(p);
    }
    max_z = std::max(max_z, tree.end(n).z());
  }
  s.height_m = max_z - tree.start(0).z();
  s.crown_width_m = projection_diameter(tree);
  s.crown_depth_m = crown_depth(tree);
  s.branches_per_order.assign(s.max_order + 1, 0);
  for (NodeId n = 0; n < tree.size(); ++n) {
    const NodeId p = tree.parent(n);
    if (tree.kind(n) != OrganKind::kInternode) continue;
    if (p == kNoNode || tree.order(n) > tree.order(p)) ++s.branches_per_order[tree.order(n)];
  }
  return s;
}

}  // namespace fspm
