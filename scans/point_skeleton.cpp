#include "scans/point_skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "fspm/error.hpp"

namespace fspm::scans {
namespace {

std::uint32_t find_set(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Set label of every point: the points of one bin joined by neighbour-graph edges.
std::vector<std::uint32_t> bin_components(const NeighbourGraph& g,
                                          const std::vector<std::int64_t>& bin) {
  const std::size_t n = bin.size();
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t e = g.offset[i]; e < g.offset[i + 1]; ++e) {
      const std::uint32_t j = g.target[e];
      if (bin[i] == bin[j]) parent[find_set(parent, i)] = find_set(parent, j);
    }
  }
  for (std::uint32_t i = 0; i < n; ++i) parent[i] = find_set(parent, i);
  return parent;
}

// Node ids ordered by bin (parents before children); fills node_of_point, first, members.
void number_nodes(const std::vector<std::uint32_t>& set, const std::vector<std::int64_t>& bin,
                  PointSkeleton& s) {
  const std::size_t n = set.size();
  std::vector<std::uint32_t> reps;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (set[i] == i) reps.push_back(i);
  }
  std::stable_sort(reps.begin(), reps.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return bin[a] < bin[b]; });
  std::vector<std::uint32_t> node_of_rep(n);
  for (std::uint32_t k = 0; k < reps.size(); ++k) node_of_rep[reps[k]] = k;
  s.node_of_point.resize(n);
  s.first.assign(reps.size() + 1, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    s.node_of_point[i] = node_of_rep[set[i]];
    ++s.first[s.node_of_point[i] + 1];
  }
  std::partial_sum(s.first.begin(), s.first.end(), s.first.begin());
  s.members.resize(n);
  std::vector<std::uint32_t> fill(s.first.begin(), s.first.end() - 1);
  for (std::uint32_t i = 0; i < n; ++i) s.members[fill[s.node_of_point[i]]++] = i;
}

}  // namespace

double default_bin_length_m(const ShortestPathTree& paths) {
  double longest = 0.0;
  for (double l : paths.path_length_m) longest = std::max(longest, l);
  return std::max(longest / 40.0, 1e-3);
}

PointSkeleton build_point_skeleton(const PointSet& ps, const NeighbourGraph& g,
                                   const ShortestPathTree& paths, double bin_length_m) {
  if (!(bin_length_m > 0.0)) throw ValueError("the bin length must be positive");
  const std::size_t n = ps.points.size();
  std::vector<std::int64_t> bin(n);
  for (std::size_t i = 0; i < n; ++i) {
    bin[i] = static_cast<std::int64_t>(std::floor(paths.path_length_m[i] / bin_length_m));
  }
  PointSkeleton s;
  number_nodes(bin_components(g, bin), bin, s);
  const std::size_t nodes = s.first.size() - 1;
  std::vector<Eigen::Vector3d> centroid(nodes, Eigen::Vector3d::Zero());
  // The node's entry: its point nearest the root among those whose predecessor lies in another
  // node (duplicate points can tie in path length with a predecessor of the same node).
  std::vector<std::uint32_t> nearest(nodes, paths.root);
  for (std::uint32_t u = 0; u < nodes; ++u) {
    double best = std::numeric_limits<double>::infinity();
    for (std::uint32_t k = s.first[u]; k < s.first[u + 1]; ++k) {
      const std::uint32_t p = s.members[k];
      centroid[u] += ps.points[p];
      const bool entry = s.node_of_point[paths.predecessor[p]] != u;
      if (entry && paths.path_length_m[p] < best) best = paths.path_length_m[p], nearest[u] = p;
    }
    centroid[u] /= static_cast<double>(s.first[u + 1] - s.first[u]);
  }
  s.tree.reserve(nodes);
  for (std::uint32_t u = 0; u < nodes; ++u) {
    const std::uint32_t pred = paths.predecessor[nearest[u]];
    const bool is_root = u == 0;
    NodeData d;
    d.start = is_root ? ps.points[paths.root] : centroid[s.node_of_point[pred]];
    d.end = centroid[u];
    s.tree.add_node(is_root ? kNoNode : s.node_of_point[pred], d);
  }
  return s;
}

}  // namespace fspm::scans
