#include "stages/skeleton_graph.hpp"

#include <algorithm>
#include <numeric>

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

// Links between joined vertices of different parts within `radius` of each other.
std::vector<WeightedEdge> near_links(const JoinedVertices& j, DisjointSets& sets, double radius) {
  const PointGrid grid(j.positions, radius);
  std::vector<WeightedEdge> edges;
  for (std::uint32_t a = 0; a < j.positions.size(); ++a) {
    grid.for_each_near(j.positions[a], radius, [&](std::uint32_t b) {
      if (a < b && sets.find(a) != sets.find(b)) {
        edges.push_back({(j.positions[a] - j.positions[b]).norm(), a, b});
      }
    });
  }
  return edges;
}

// For parts still apart: the shortest link from each part to any other, until one part is left
// (Boruvka's rounds; each at least halves the number of parts).
void link_remaining(const JoinedVertices& j, DisjointSets& sets, std::vector<SkeletonEdge>& tree) {
  const auto n = static_cast<std::uint32_t>(j.positions.size());
  const auto parts = [&] {
    std::size_t roots = 0;
    for (std::uint32_t a = 0; a < n; ++a) roots += sets.find(a) == a;
    return roots;
  };
  while (parts() > 1) {
    std::vector<WeightedEdge> best(n, WeightedEdge{INFINITY, 0, 0});
    for (std::uint32_t a = 0; a < n; ++a) {
      for (std::uint32_t b = a + 1; b < n; ++b) {
        const std::uint32_t pa = sets.find(a), pb = sets.find(b);
        if (pa == pb) continue;
        const WeightedEdge e{(j.positions[a] - j.positions[b]).norm(), a, b};
        if (e < best[pa]) best[pa] = e;
        if (e < best[pb]) best[pb] = e;
      }
    }
    std::vector<WeightedEdge> links;
    for (const WeightedEdge& e : best) {
      if (e.length < INFINITY) links.push_back(e);
    }
    add_spanning(std::move(links), sets, tree);
  }
}

}  // namespace

std::vector<SkeletonEdge> skeleton_spanning_tree(
    const JoinedVertices& joined, const std::vector<std::array<std::uint32_t, 3>>& triangles,
    double link_radius) {
  DisjointSets sets(joined.positions.size());
  std::vector<SkeletonEdge> tree;
  add_spanning(mesh_edges(joined, triangles), sets, tree);
  add_spanning(near_links(joined, sets, link_radius), sets, tree);
  link_remaining(joined, sets, tree);
  return tree;
}

}  // namespace fspm::stages
