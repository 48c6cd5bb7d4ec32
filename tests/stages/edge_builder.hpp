#pragma once
// Hand-built trees for the stages tests: one straight edge at a time.
#include <Eigen/Core>

#include "fspm/tree_graph.hpp"

namespace fspm::stages::testing {

// An edge under `parent` (from its end; from the origin for the root) along `dir` (normalized
// here) of `length` and radius `r`.
inline NodeId edge(TreeGraph& t, NodeId parent, const Eigen::Vector3d& dir, double length,
                   double r) {
  NodeData d;
  d.start = parent == kNoNode ? Eigen::Vector3d::Zero() : t.end(parent);
  d.direction = dir.normalized();
  d.end = d.start + length * d.direction;
  d.length = length;
  d.radius = r;
  return t.add_node(parent, d);
}

}  // namespace fspm::stages::testing
