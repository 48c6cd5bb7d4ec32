#include "scans/shortest_path_tree.hpp"

#include <algorithm>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths_no_color_map.hpp>

namespace fspm::scans {

std::uint32_t lowest_point(const PointSet& ps) {
  std::uint32_t best = 0;
  for (std::uint32_t i = 1; i < ps.points.size(); ++i) {
    if (ps.points[i].z() < ps.points[best].z()) best = i;
  }
  return best;
}

ShortestPathTree shortest_path_tree(const PointSet& ps, const NeighbourGraph& g,
                                    std::uint32_t root) {
  using Graph =
      boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, float,
                                         boost::no_property, std::uint32_t, std::uint32_t>;
  const std::size_t n = ps.points.size();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  edges.reserve(g.target.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t e = g.offset[i]; e < g.offset[i + 1]; ++e)
      edges.emplace_back(i, g.target[e]);
  }
  const Graph graph(boost::edges_are_sorted, edges.begin(), edges.end(), g.weight.begin(), n);
  edges = {};
  ShortestPathTree t;
  t.root = root;
  t.predecessor.resize(n);
  std::vector<float> distance(n);
  boost::dijkstra_shortest_paths_no_color_map(
      graph, root,
      boost::predecessor_map(t.predecessor.data())
          .distance_map(distance.data())
          .weight_map(boost::get(boost::edge_bundle, graph)));
  // Path lengths by walking up to the nearest point already known; every point is walked once.
  t.path_length_m.assign(n, -1.0);
  t.path_length_m[root] = 0.0;
  std::vector<std::uint32_t> stack;
  for (std::uint32_t v = 0; v < n; ++v) {
    std::uint32_t u = v;
    while (t.path_length_m[u] < 0.0 && t.predecessor[u] != u) {
      stack.push_back(u);
      u = t.predecessor[u];
    }
    if (t.path_length_m[u] < 0.0) t.path_length_m[u] = 0.0;  // unreachable: its own root
    for (; !stack.empty(); stack.pop_back()) {
      const std::uint32_t w = stack.back();
      const std::uint32_t p = t.predecessor[w];
      t.path_length_m[w] = t.path_length_m[p] + (ps.points[w] - ps.points[p]).norm();
    }
  }
  return t;
}

}  // namespace fspm::scans
