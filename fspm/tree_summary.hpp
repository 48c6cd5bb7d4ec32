#pragma once
// Summary figures of a tree, as `fspm tree info` prints them.
#include <cstddef>

#include "fspm/tree_graph.hpp"

namespace fspm {

struct TreeSummary {
  std::size_t nodes = 0;
  std::size_t internodes = 0;
  std::size_t leaves = 0;  // organ kind leaf
  std::size_t flowers = 0;
  std::size_t buds = 0;
  std::size_t tips = 0;  // nodes without children
  std::size_t max_order = 0;
  std::size_t max_depth = 0;    // edges on the longest root-to-tip path
  double height_m = 0.0;        // highest z of any node end minus the root's start z
  double total_length_m = 0.0;  // summed length of internodes
  Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero();
  Eigen::Vector3d bbox_max = Eigen::Vector3d::Zero();
  // Largest distance between two points of the tree's ground projection (m).
  double crown_width_m = 0.0;
  // Top of the tree minus the crown base, the lowest lateral (order >= 1) node or leaf (m).
  double crown_depth_m = 0.0;
  // Branch axes per branching order: [0] the main stem (1), [k] axes of order k, counted at their
  // first internode (one whose order exceeds its parent's).
  std::vector<std::size_t> branches_per_order;
};

TreeSummary summarize(const TreeGraph& tree);

}  // namespace fspm
