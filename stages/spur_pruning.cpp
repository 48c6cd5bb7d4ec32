#include "stages/spur_pruning.hpp"

#include <algorithm>

namespace fspm::stages {

std::vector<SkeletonEdge> prune_spurs(const std::vector<SkeletonEdge>& edges,
                                      const std::vector<Eigen::Vector3d>& positions,
                                      double min_length) {
  std::vector<std::vector<std::uint32_t>> adj(positions.size());
  for (const auto& [a, b] : edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  std::vector<bool> removed(positions.size(), false);
  for (std::uint32_t end = 0; end < adj.size(); ++end) {
    if (adj[end].size() != 1) continue;
    // Walk from the end to the first fork (a vertex with three or more links).
    std::vector<std::uint32_t> run{end};
    double length = 0.0;
    std::uint32_t prev = end, at = adj[end][0];
    while (adj[at].size() == 2 && length < min_length) {
      length += (positions[at] - positions[prev]).norm();
      run.push_back(at);
      const std::uint32_t next = adj[at][0] == prev ? adj[at][1] : adj[at][0];
      prev = at;
      at = next;
    }
    length += (positions[at] - positions[prev]).norm();
    if (adj[at].size() >= 3 && length < min_length) {
      for (const std::uint32_t v : run) removed[v] = true;
    }
  }
  std::vector<SkeletonEdge> out;
  for (const auto& e : edges) {
    if (!removed[e.first] && !removed[e.second]) out.push_back(e);
  }
  return out;
}

}  // namespace fspm::stages
