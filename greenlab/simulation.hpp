#pragma once
// Structural simulation of the dual-scale automaton (Zhao 2003) by substructure factorization
// (Yan et al. 2002, Jaeger 2.1.3): the substructure S(p, t) grown by an apex of physiological age
// p from cycle t is built once and shared by every bud that starts it, so the cost grows with
// cycles x physiological ages, not with the number of metamers. Stochastic (GL2) ages are built
// per instance, drawing from the generator passed in; deterministic parts stay shared.
#include <cstdint>
#include <map>
#include <random>

#include "fspm/compressed_tree_graph.hpp"
#include "greenlab/plant_params.hpp"

namespace fspm::greenlab {

// Metamers born at cycle 1..cycles, starting from one bud of age 1 at cycle 1. Multiplicities are
// computed; records are numbered depth first from the root (successor before laterals), which
// reproduces the numbering of Jaeger's node tables. The per-age geometry is stored in the
// graph's metadata for the reconstruction. `cycles` < 0 means params.cycles.
CompressedTreeGraph simulate_compressed(const PlantParams& params, std::mt19937_64& rng,
                                        int cycles = -1);
CompressedTreeGraph simulate_compressed(const PlantParams& params, int cycles = -1);

// Counts of the plant a graph stands for.
struct OrganCounts {
  std::uint64_t metamers = 0;
  std::uint64_t leaves = 0;   // living at the graph's final age
  std::uint64_t flowers = 0;  // terminal flowers
  std::uint64_t buds = 0;     // living apical buds
  std::map<int, std::uint64_t> metamers_by_age;
};
// Leaf life spans come from the per-age metadata stored by simulate_compressed.
OrganCounts count_organs(const CompressedTreeGraph& graph);

// Uniform number in [0, 1) from the generator, the same on every platform.
double uniform01(std::mt19937_64& rng);

}  // namespace fspm::greenlab
