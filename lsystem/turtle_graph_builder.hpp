#pragma once
// The turtle visitor that draws into a tree graph: one internode per F, a leaf node per polygon
// { . } (area by Newell's formula) or predefined surface ~x, a flower per sphere @o. Shared by
// the explicit interpretation (turtle.cpp) and the instanced one (instanced_interpretation.cpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "fspm/attribute_names.hpp"
#include "lsystem/turtle.hpp"
#include "lsystem/turtle_core.hpp"

namespace fspm::lsystem::detail {

class GraphBuilder {
 public:
  explicit GraphBuilder(Interpretation& out) : out_(out) {}

  void forward(const Eigen::Vector3d& start, const Eigen::Vector3d& heading, double length,
               Frame& f) {
    NodeData d;
    d.start = start;
    d.end = f.position;
    d.direction = heading;
    d.length = std::abs(length);
    d.radius = 0.5 * f.width;  // the line width is the diameter (cpfg polygons, cylinders)
    d.order = static_cast<std::uint16_t>(std::min(f.depth, 65535));
    d.kind = OrganKind::kInternode;
    f.node = add(f.node, d, f.color);
    line_width_nodes_.push_back(f.node);
  }
  void polygon_begin(const Frame& f) { polygons_.push_back({f.node, {}}); }
  void vertex(const Eigen::Vector3d& v) {
    if (polygons_.empty()) return;
    auto& vs = polygons_.back().second;
    if (vs.empty() || !vs.back().isApprox(v, 1e-12)) vs.push_back(v);
  }
  void polygon_end(const Frame& f) {
    auto [parent, vs] = std::move(polygons_.back());
    polygons_.pop_back();
    if (vs.size() >= 2 && vs.front().isApprox(vs.back(), 1e-12)) vs.pop_back();
    if (vs.size() < 3) return;
    // Newell's formula: area = |sum v_i x v_{i+1}| / 2.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    std::size_t far = 0;
    double far_d = -1.0;
    for (std::size_t k = 0; k < vs.size(); ++k) {
      normal += vs[k].cross(vs[(k + 1) % vs.size()]);
      const double dist = (vs[k] - vs[0]).squaredNorm();
      if (dist > far_d) {
        far_d = dist;
        far = k;
      }
    }
    NodeData d;
    d.start = vs[0];
    d.end = vs[far];
    d.direction = (vs[far] - vs[0]).normalized();
    d.length = std::sqrt(far_d);
    d.order = static_cast<std::uint16_t>(std::min(f.depth, 65535));
    d.kind = OrganKind::kLeaf;
    const NodeId id = add(parent, d, f.color);
    out_.leaves.push_back({id, std::move(vs), 0.5 * normal.norm()});
  }
  void surface(double scale, const Frame& f) {
    NodeData d;
    d.start = f.position;
    d.end = f.position + f.heading * scale;
    d.direction = f.heading;
    d.length = std::abs(scale);
    d.order = static_cast<std::uint16_t>(std::min(f.depth, 65535));
    d.kind = OrganKind::kLeaf;
    add(f.node, d, f.color);
  }
  // cpfg @o(d): a sphere of diameter d, recorded as a flower organ at the turtle position.
  // Without d the sphere takes the line width (and its unit).
  void sphere(double diameter, bool line_width, const Frame& f) {
    NodeData d;
    d.start = f.position;
    d.end = f.position;
    d.direction = f.heading;
    d.length = 0.0;
    d.radius = std::abs(diameter) * 0.5;
    d.order = static_cast<std::uint16_t>(std::min(f.depth, 65535));
    d.kind = OrganKind::kFlower;
    const NodeId id = add(f.node, d, f.color);
    if (line_width) line_width_nodes_.push_back(id);
  }
  void query(std::size_t, Action, const Frame&) {}

  // The colour of every node ("color_index") and the area of every polygon leaf ("leaf_area").
  void store_attributes() {
    out_.tree.add_attribute("color_index");
    auto colors = out_.tree.attribute("color_index");
    std::copy(colors_.begin(), colors_.end(), colors.begin());
    if (!out_.leaves.empty()) {
      out_.tree.add_attribute(kLeafAreaAttribute);
      auto area = out_.tree.attribute(kLeafAreaAttribute);
      for (const LeafPolygon& leaf : out_.leaves) area[leaf.node] = leaf.area;
    }
  }

  std::vector<double> colors_;
  std::vector<NodeId> line_width_nodes_;  // radius = half a line width, in the width's unit

 private:
  NodeId add(NodeId parent, const NodeData& d, int color) {
    // A graph has one root: modules drawn before any internode (or after popping back to the
    // base) hang from the first internode.
    if (parent == kNoNode && !out_.tree.empty()) parent = 0;
    const NodeId id = out_.tree.add_node(parent, d);
    colors_.push_back(color);
    return id;
  }

  Interpretation& out_;
  std::vector<std::pair<NodeId, std::vector<Eigen::Vector3d>>> polygons_;
};

}  // namespace fspm::lsystem::detail
