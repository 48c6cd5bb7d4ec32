#include "stages/skeleton_tree.hpp"

#include <algorithm>
#include <deque>

#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

using Adjacency = std::vector<std::vector<std::uint32_t>>;

std::uint32_t lowest_end(const JoinedVertices& j, const Adjacency& adj) {
  std::uint32_t best = UINT32_MAX;
  for (int pass = 0; pass < 2 && best == UINT32_MAX; ++pass) {
    for (std::uint32_t i = 0; i < adj.size(); ++i) {
      if (adj[i].empty() || (pass == 0 && adj[i].size() > 1)) continue;  // ends first
      if (best == UINT32_MAX || j.positions[i].z() < j.positions[best].z()) best = i;
    }
  }
  return best;
}

// Skeleton positions: the averages (eq. 5.2), each end moved out along its edge as far as its
// original vertices reach (the contraction pulls a tube's ends inward by about half a radius).
std::vector<Eigen::Vector3d> node_positions(const JoinedVertices& j, const Adjacency& adj,
                                            const std::vector<Eigen::Vector3d>& original) {
  std::vector<Eigen::Vector3d> p = j.positions;
  for (std::uint32_t i = 0; i < adj.size(); ++i) {
    if (adj[i].size() != 1) continue;
    const Eigen::Vector3d& neighbour = j.positions[adj[i][0]];
    const Eigen::Vector3d dir = (p[i] - neighbour).normalized();
    double reach = (p[i] - neighbour).norm();
    for (const std::uint32_t v : j.members[i])
      reach = std::max(reach, (original[v] - neighbour).dot(dir));
    p[i] = neighbour + reach * dir;
  }
  return p;
}

double edge_radius(const JoinedVertices& j, const std::vector<Eigen::Vector3d>& original,
                   const Eigen::Vector3d& a, const Eigen::Vector3d& b, std::uint32_t pa,
                   std::uint32_t pb) {
  const Eigen::Vector3d axis = b - a;
  const double len2 = axis.squaredNorm();
  double sum = 0.0;
  std::size_t count = 0;
  for (const std::uint32_t node : {pa, pb}) {
    for (const std::uint32_t v : j.members[node]) {
      const double t = len2 > 0.0 ? (original[v] - a).dot(axis) / len2 : -1.0;
      if (t <= 0.0 || t >= 1.0) continue;
      sum += (original[v] - (a + t * axis)).norm();
      ++count;
    }
  }
  if (count > 0) return sum / static_cast<double>(count);
  for (const std::uint32_t v : j.members[pb]) sum += (original[v] - b).norm();
  return sum / static_cast<double>(std::max<std::size_t>(j.members[pb].size(), 1));
}

}  // namespace

TreeGraph skeleton_tree(const JoinedVertices& joined, const std::vector<SkeletonEdge>& edges,
                        const std::vector<Eigen::Vector3d>& original) {
  const std::size_t n = joined.positions.size();
  if (n < 2) {
    throw ValueError(
        "the contracted mesh joined into a single point: no skeleton edge (give a "
        "smaller joining distance)");
  }
  Adjacency adj(n);
  for (const auto& [a, b] : edges) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  const std::vector<Eigen::Vector3d> pos = node_positions(joined, adj, original);
  const std::uint32_t root = lowest_end(joined, adj);
  if (root == UINT32_MAX) throw ValueError("the skeleton has no edge");
  // Breadth first from the root: parents get their internode before their children.
  std::vector<NodeId> internode(n, kNoNode);
  std::vector<bool> seen(n, false);
  std::deque<std::uint32_t> queue{root};
  seen[root] = true;
  TreeGraph tree;
  tree.reserve(n - 1);
  while (!queue.empty()) {
    const std::uint32_t p = queue.front();
    queue.pop_front();
    for (const std::uint32_t c : adj[p]) {
      if (seen[c]) continue;
      seen[c] = true;
      queue.push_back(c);
      NodeData d;
      d.start = pos[p];
      d.end = pos[c];
      d.radius = edge_radius(joined, original, pos[p], pos[c], p, c);
      const NodeId parent = p == root ? (tree.empty() ? kNoNode : NodeId{0}) : internode[p];
      internode[c] = tree.add_node(parent, d);
    }
  }
  return tree;
}

}  // namespace fspm::stages
