#pragma once
// Orders in which to visit a TreeGraph. All are iterative (no recursion), so depth is unlimited.
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm {

// Parent before children, children in insertion order, depth first.
std::vector<NodeId> preorder(const TreeGraph& tree, NodeId from = 0);
// Children before parent, depth first.
std::vector<NodeId> postorder(const TreeGraph& tree, NodeId from = 0);

// Axes: maximal sequences of nodes where each node continues its parent's axis (same branching
// order). The first axis is the trunk; an axis starts at the root or at a node whose order is
// greater than its parent's. Nodes in each axis run from base to tip.
std::vector<std::vector<NodeId>> axes(const TreeGraph& tree);

// Nodes grouped by branching order: result[k] holds the nodes of order k, in id order.
std::vector<std::vector<NodeId>> nodes_by_order(const TreeGraph& tree);

// Chains: maximal runs of nodes without branching. A chain starts at the root or at a child of
// a node with two or more children, and continues while the current node has exactly one child.
std::vector<std::vector<NodeId>> chains(const TreeGraph& tree);

}  // namespace fspm
