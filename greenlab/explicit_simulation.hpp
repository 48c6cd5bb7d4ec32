#pragma once
// The plain simulation: cycle by cycle, every apex grows its growth unit into an explicit list of
// metamers. Exponential in cost; it exists as the test oracle of the factorized simulation.
#include <cstdint>
#include <random>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "greenlab/plant_params.hpp"

namespace fspm::greenlab {

struct ExplicitMetamer {
  int age = 1;
  double birth = 0.0;
  std::int64_t successor = -1;
  std::vector<std::int64_t> laterals;  // first metamers of the lateral axes, in bud order
  ApexState apex = ApexState::kNone;
};

struct ExplicitPlant {
  std::vector<ExplicitMetamer> metamers;  // metamers[0] is the first metamer of the trunk
};

ExplicitPlant simulate_explicit(const PlantParams& params, std::mt19937_64& rng, int cycles = -1);

// One entry per metamer in depth-first order (successor before laterals): what an expansion of
// the compressed graph must reproduce exactly.
struct CanonicalMetamer {
  int age;
  double birth;
  int order;
  ApexState apex;
  std::size_t laterals;
  bool has_successor;
  bool operator==(const CanonicalMetamer&) const = default;
};
std::vector<CanonicalMetamer> canonical_sequence(const ExplicitPlant& plant);
std::vector<CanonicalMetamer> canonical_sequence(const CompressedTreeGraph& graph);

}  // namespace fspm::greenlab
