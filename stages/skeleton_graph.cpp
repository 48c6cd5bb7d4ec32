#include "stages/skeleton_graph.hpp"

#include <algorithm>
#include <numeric>
#include <tuple>

#include "stages/point_grid.hpp"

namespace fspm::stages {
namespace {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0u);
  }
  std::uint32_t find(std::uint32_t i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[b] = a;
    return true;
  }

 private:
  std::vector<std::uint32_t> parent_;
};

struct WeightedEdge {
  double length;
  std::uint32_t a, b;
  bool operator<(const WeightedEdge& o) const {
    return length != o.length ? length < o.length : (a != o.a ? a < o.a : b < o.b);
  }
};

// Kruskal: adds the edges in order of length that join two parts.
void add_spanning(std::vector<WeightedEdge> edges, DisjointSets& sets,
                  std::vector<SkeletonEdge>& tree) {
  std::sort(edges.begin(), edges.end());
  for (const WeightedEdge& e : edges) {
    if (sets.unite(e.a, e.b)) tree.emplace_back(e.a, e.b);
  }
}

std::vector<WeightedEdge> mesh_edges(const JoinedVertices& j,
                                     const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<WeightedEdge> edges;
  for (const auto& f : triangles) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = j.node_of[f[k]], b = j.node_of[f[(k + 1) % 3]];
      if (a == b) continue;
      if (a > b) std::swap(a, b);
      edges.push_back({(j.positions[a] - j.positions[b]).norm(), a, b});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const WeightedEdge& x, const WeightedEdge& y) {
                            return x.a == y.a && x.b == y.b;
                          }),
              edges.end());
  return edges;
}

// Links between joined vertices of different parts within `radius` of each other, searched from
// the vertices outside the part `skip` (the largest: searching from it finds nothing new).
std::vector<WeightedEdge> near_links(const JoinedVertices& j, const PointGrid& grid,
                                     DisjointSets& sets, double radius, std::uint32_t skip) {
  std::vector<WeightedEdge> edges;
  for (std::uint32_t a = 0; a < j.positions.size(); ++a) {
    if (sets.find(a) == skip) continue;
    grid.for_each_near(j.positions[a], radius, [&](std::uint32_t b) {
      if (sets.find(a) != sets.find(b)) {
        edges.push_back({(j.positions[a] - j.positions[b]).norm(), std::min(a, b), std::max(a, b)});
      }
    });
  }
  return edges;
}

// The root of the largest part and the number of parts.
std::pair<std::uint32_t, std::size_t> largest_part(DisjointSets& sets, std::size_t n) {
  std::vector<std::uint32_t> size(n, 0);
  std::uint32_t best = 0;
  std::size_t parts = 0;
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::uint32_t r = sets.find(a);
    parts += ++size[r] == 1;
    if (size[r] > size[best]) best = r;
  }
  return {best, parts};
}

// Links parts within `radius`, then, while parts are still apart, within twice the radius, and
// so on: each round joins every part to its nearest neighbours within reach (Kruskal over the
// candidates, so the shortest links win). Each round's grid has cells of its radius, so a search
// visits a few cells: with the first round's cells, a gap of a million radii (a joining distance
// of 1e-320 m) would have each search visit 10^18 of them.
void link_parts(const JoinedVertices& j, DisjointSets& sets, double radius,
                std::vector<SkeletonEdge>& tree) {
  for (auto [largest, parts] = largest_part(sets, j.positions.size()); parts > 1; radius *= 2.0) {
    const PointGrid grid(j.positions, radius);
    add_spanning(near_links(j, grid, sets, radius, largest), sets, tree);
    std::tie(largest, parts) = largest_part(sets, j.positions.size());
  }
}

}  // namespace

std::vector<SkeletonEdge> skeleton_spanning_tree(
    const JoinedVertices& joined, const std::vector<std::array<std::uint32_t, 3>>& triangles,
    double link_radius) {
  DisjointSets sets(joined.positions.size());
  std::vector<SkeletonEdge> tree;
  add_spanning(mesh_edges(joined, triangles), sets, tree);
  link_parts(joined, sets, link_radius, tree);
  return tree;
}

}  // namespace fspm::stages
