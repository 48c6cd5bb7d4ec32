#include "scans/tip_pruning.hpp"

#include <vector>

namespace fspm::scans {

std::vector<std::uint8_t> short_tip_nodes(const TreeGraph& t, double min_length_m) {
  std::vector<std::uint8_t> drop(t.size(), 0);
  for (NodeId tip = 0; tip < t.size(); ++tip) {
    if (!t.children(tip).empty()) continue;
    std::vector<NodeId> chain{tip};
    double length = t.length(tip);
    NodeId u = tip;
    while (t.parent(u) != kNoNode && t.child_count(t.parent(u)) == 1) {
      u = t.parent(u), chain.push_back(u), length += t.length(u);
    }
    const NodeId fork = t.parent(u);
    // The axis continues into the sibling of the largest order-keeping subtree: keep a chain whose
    // order is its fork's (set_branch_orders), drop a side tip.
    if (fork == kNoNode || t.order(u) == t.order(fork) || length >= min_length_m) continue;
    for (NodeId c : chain) drop[c] = 1;
  }
  return drop;
}

TreeGraph without_short_tips(const TreeGraph& t, double min_length_m) {
  const std::vector<std::uint8_t> drop = short_tip_nodes(t, min_length_m);
  TreeGraph out;
  std::vector<NodeId> map(t.size(), kNoNode);
  for (NodeId u = 0; u < t.size(); ++u) {
    if (drop[u] != 0) continue;
    const NodeId p = t.parent(u);
    map[u] = out.add_node(p == kNoNode ? kNoNode : map[p], t.data(u));
  }
  return out;
}

}  // namespace fspm::scans
