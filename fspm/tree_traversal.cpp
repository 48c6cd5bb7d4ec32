#include "fspm/tree_traversal.hpp"

#include <algorithm>

namespace fspm {

std::vector<NodeId> preorder(const TreeGraph& tree, NodeId from) {
  std::vector<NodeId> out;
  if (tree.empty()) return out;
  out.reserve(from == 0 ? tree.size() : 64);
  std::vector<NodeId> stack{from};
  std::vector<NodeId> kids;
  while (!stack.empty()) {
    const NodeId n = stack.back();
    stack.pop_back();
    out.push_back(n);
    // Push children in reverse so the first child is visited first.
    kids.clear();
    for (NodeId c : tree.children(n)) kids.push_back(c);
    stack.insert(stack.end(), kids.rbegin(), kids.rend());
  }
  return out;
}

std::vector<NodeId> postorder(const TreeGraph& tree, NodeId from) {
  std::vector<NodeId> out;
  if (tree.empty()) return out;
  // (node, next child to visit) pairs; a node is emitted after its last child.
  std::vector<std::pair<NodeId, NodeId>> stack{{from, tree.first_child(from)}};
  while (!stack.empty()) {
    auto& [n, next] = stack.back();
    if (next == kNoNode) {
      out.push_back(n);
      stack.pop_back();
    } else {
      const NodeId c = next;
      next = tree.next_sibling(c);
      stack.emplace_back(c, tree.first_child(c));
    }
  }
  return out;
}

std::vector<std::vector<NodeId>> axes(const TreeGraph& tree) {
  std::vector<std::vector<NodeId>> out;
  if (tree.empty()) return out;
  std::vector<std::size_t> axis_of(tree.size());
  // Ids are topologically ordered (parents first), so one forward pass assigns every node.
  for (NodeId n = 0; n < tree.size(); ++n) {
    const NodeId p = tree.parent(n);
    if (p != kNoNode && tree.order(n) == tree.order(p) && out[axis_of[p]].back() == p) {
      axis_of[n] = axis_of[p];
    } else {
      axis_of[n] = out.size();
      out.emplace_back();
    }
    out[axis_of[n]].push_back(n);
  }
  return out;
}

std::vector<std::vector<NodeId>> nodes_by_order(const TreeGraph& tree) {
  std::vector<std::vector<NodeId>> out;
  for (NodeId n = 0; n < tree.size(); ++n) {
    const std::size_t k = tree.order(n);
    if (out.size() <= k) out.resize(k + 1);
    out[k].push_back(n);
  }
  return out;
}

std::vector<std::vector<NodeId>> chains(const TreeGraph& tree) {
  std::vector<std::vector<NodeId>> out;
  if (tree.empty()) return out;
  std::vector<NodeId> starts{0};
  while (!starts.empty()) {
    NodeId n = starts.back();
    starts.pop_back();
    std::vector<NodeId> chain{n};
    while (tree.child_count(n) == 1) {
      n = tree.first_child(n);
      chain.push_back(n);
    }
    for (NodeId c : tree.children(n)) starts.push_back(c);
    out.push_back(std::move(chain));
  }
  return out;
}

}  // namespace fspm
