#pragma once
// Small hand-built trees for the graphics tests, with their structure known in closed form.
#include <cmath>

#include "fspm/tree_graph.hpp"

namespace fspm::graphics::testing {

inline NodeId add(TreeGraph& t, NodeId parent, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                  double radius, double birth, std::uint16_t order,
                  OrganKind kind = OrganKind::kInternode) {
  NodeData d;
  d.start = a;
  d.end = b;
  d.radius = radius;
  d.birth_time = birth;
  d.order = order;
  d.kind = kind;
  return t.add_node(parent, d);
}

// Trunk of three internodes (radius 0.05, born 0, 1, 2) up the z axis, bending slightly; at its
// top two branches of two internodes each (radius 0.01, born 3 and 4); a leaf on each branch
// tip and one on the trunk's middle node. A "light" attribute = 10 * node id.
inline TreeGraph small_tree() {
  TreeGraph t;
  const Eigen::Vector3d o(0, 0, 0), a(0, 0, 1), b(0.1, 0, 2), c(0.1, 0.1, 3);
  const NodeId n0 = add(t, kNoNode, o, a, 0.05, 0, 0);
  const NodeId n1 = add(t, n0, a, b, 0.05, 1, 0);
  add(t, n1, b, b + Eigen::Vector3d(0.2, 0, 0), 0.0, 1.5, 1, OrganKind::kLeaf);
  const NodeId n2 = add(t, n1, b, c, 0.05, 2, 0);
  for (int side = -1; side <= 1; side += 2) {
    const Eigen::Vector3d d1 = c + Eigen::Vector3d(0.5 * side, 0, 0.5);
    const Eigen::Vector3d d2 = d1 + Eigen::Vector3d(0.4 * side, 0.1, 0.4);
    const NodeId m1 = add(t, n2, c, d1, 0.01, 3, 1);
    const NodeId m2 = add(t, m1, d1, d2, 0.01, 4, 1);
    add(t, m2, d2, d2 + Eigen::Vector3d(0.1 * side, 0, 0.1), 0.0, 4.5, 2, OrganKind::kLeaf);
  }
  t.add_attribute("light", 0.0);
  auto light = t.attribute("light");
  for (NodeId id = 0; id < t.size(); ++id) light[id] = 10.0 * id;
  return t;
}

// A binary tree of internodes `depth` levels deep, each branch `segments` internodes long.
// Sibling branches start at the same point, so their rings may touch there; the "branch"
// attribute tells the branches apart.
inline TreeGraph binary_tree(int depth, int segments, double radius = 0.05) {
  TreeGraph t;
  t.add_attribute("branch", 0.0);  // one value per chain: tests weld vertices within a branch
  double branch = 0.0;
  struct Item {
    NodeId parent;
    Eigen::Vector3d base, dir;
    int level;
    double r;
  };
  std::vector<Item> stack{{kNoNode, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), 0, radius}};
  while (!stack.empty()) {
    Item it = stack.back();
    stack.pop_back();
    NodeId last = it.parent;
    Eigen::Vector3d p = it.base;
    const double len = 1.0 / (1 + it.level);
    for (int s = 0; s < segments; ++s) {
      const Eigen::Vector3d q = p + len * it.dir;
      last = add(t, last, p, q, it.r, it.level + 0.1 * s, static_cast<std::uint16_t>(it.level));
      t.attribute("branch")[last] = branch;
      p = q;
    }
    branch += 1.0;
    if (it.level + 1 < depth) {
      const double ang = 0.5 + 0.3 * it.level;
      for (int side = -1; side <= 1; side += 2) {
        Eigen::Vector3d d = std::cos(ang) * it.dir + std::sin(ang) * side *
                                                         (it.level % 2 ? Eigen::Vector3d::UnitX()
                                                                       : Eigen::Vector3d::UnitY());
        stack.push_back({last, p, d.normalized(), it.level + 1, it.r * 0.7});
      }
    }
  }
  return t;
}

// Trunk of four internodes up z (order 0, r 0.1); laterals (order 1, r 0.03, two internodes)
// leave from the tops of nodes 1 and 2 at 60 degrees from the trunk, in different directions.
inline TreeGraph junction_tree() {
  TreeGraph t;
  NodeId prev = kNoNode;
  std::vector<NodeId> trunk;
  for (int i = 0; i < 4; ++i) {
    prev = add(t, prev, Eigen::Vector3d(0, 0, i), Eigen::Vector3d(0, 0, i + 1), 0.1, i, 0);
    trunk.push_back(prev);
  }
  for (int k = 0; k < 2; ++k) {
    const double az = 0.4 + 2.5 * k;
    const Eigen::Vector3d d(std::sin(M_PI / 3) * std::cos(az), std::sin(M_PI / 3) * std::sin(az),
                            std::cos(M_PI / 3));
    Eigen::Vector3d p(0, 0, 2 + k);
    NodeId parent = trunk[1 + k];
    for (int s = 0; s < 2; ++s) {
      parent = add(t, parent, p, p + 0.6 * d, 0.03, 2 + k + s, 1);
      p += 0.6 * d;
    }
  }
  return t;
}

}  // namespace fspm::graphics::testing
