#pragma once
// Random tree graphs for property tests: random shape, random geometry, random attributes.
#include <random>

#include "fspm/tree_graph.hpp"

namespace fspm::testing {

inline TreeGraph random_tree(std::mt19937_64& rng, std::size_t nodes, int attributes = 2) {
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::uniform_int_distribution<int> kind(0, 3);
  TreeGraph t;
  for (int a = 0; a < attributes; ++a) t.add_attribute("attr" + std::to_string(a), u(rng));
  for (std::size_t i = 0; i < nodes; ++i) {
    NodeData d;
    d.start = {u(rng), u(rng), u(rng)};
    d.end = {u(rng), u(rng), u(rng)};
    d.radius = std::abs(u(rng)) * 1e-3;
    d.birth_time = u(rng) * 1e7;
    d.physiological_age = static_cast<std::uint16_t>(kind(rng) + 1);
    d.order = static_cast<std::uint16_t>(kind(rng));
    d.kind = static_cast<OrganKind>(kind(rng));
    const NodeId parent =
        i == 0 ? kNoNode
               : static_cast<NodeId>(std::uniform_int_distribution<std::size_t>(0, i - 1)(rng));
    const NodeId n = t.add_node(parent, d);
    for (int a = 0; a < attributes; ++a) {
      t.attribute("attr" + std::to_string(a))[n] = u(rng) * std::pow(10.0, kind(rng) * 7 - 10);
    }
  }
  return t;
}

}  // namespace fspm::testing
