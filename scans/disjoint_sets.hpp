#pragma once
// Disjoint sets (union-find with path halving) over the indices 0 .. n - 1.
#include <cstdint>
#include <numeric>
#include <vector>

namespace fspm::scans {

struct DisjointSets {
  std::vector<std::uint32_t> parent;
  explicit DisjointSets(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t find(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

}  // namespace fspm::scans
