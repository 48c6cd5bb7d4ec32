#pragma once
// Derivation into shared substructures (Jaeger et al. 2010, 2.1.3, for any context-free
// L-system). In a context-free L-system without per-step side effects, a module with given
// parameters always becomes the same string after k more steps, wherever it stands. The derived
// string is therefore a directed acyclic graph of substructures keyed by (module, parameters,
// remaining steps), each computed once and referenced wherever it recurs: ABOP Fig. 1.24a at
// n = 20 (about 2 * 10^14 modules) is a graph of a few hundred nodes.
//
// Parameters compare exactly (bit for bit). L-systems whose rewriting depends on where or when a
// module stands (context-sensitive or stochastic productions, random numbers, assignments to
// global variables, per-step blocks, cut `%`, environment queries) cannot be factorized:
// factorization_obstacle() names the first reason.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lsystem/derivation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/module_string.hpp"

namespace fspm::lsystem {

// One substructure: module `symbol` (with its parameters) after `remaining` more steps. A leaf
// (remaining == 0, or a module no production changes) stands for the module itself; otherwise
// its string is the concatenation of its children's strings.
struct Substructure {
  SymbolId symbol = 0;
  std::uint32_t parameter_begin = 0;  // into SubstructureGraph::parameters
  std::uint32_t parameter_count = 0;
  std::uint32_t child_begin = 0;  // into SubstructureGraph::children
  std::uint32_t child_count = 0;
  int remaining = 0;
  bool leaf() const { return child_count == 0; }
};

struct SubstructureGraph {
  std::vector<Substructure> nodes;  // children before their parents
  std::vector<std::uint32_t> children;
  std::vector<double> parameters;
  std::vector<std::uint32_t> axiom;  // the derived string: these substructures in order
  int steps = 0;
  bool parametric = false;  // some module carries parameters

  // Bytes held by the graph's arrays.
  std::size_t memory_bytes() const;
};

// Module counts of the expanded string, computed on the graph. Counts saturate at 2^64 - 1
// (`saturated` then says that some count is at least that).
struct SubstructureCounts {
  bool saturated = false;
  std::uint64_t modules = 0;
  std::vector<std::uint64_t> per_symbol;  // indexed by SymbolId
  // Bytes the explicit string would take in a ModuleString (2 per module, plus 4 per module
  // and 8 per parameter when parametric).
  std::uint64_t explicit_bytes = 0;
};

// Why `system` cannot be derived into substructures, or nothing when it can. With `variants`,
// stochastic productions are no obstacle (see derive_substructures).
std::optional<std::string> factorization_obstacle(const LSystem& system, bool variants = false);

// Why the homomorphism productions of `system` cannot be applied module by module (the same
// reasons as for productions), or nothing when they can.
std::optional<std::string> homomorphism_obstacle(const LSystem& system);

// Derives `system` into substructures for options.steps (or its derivation length) steps.
// options.module_budget bounds the number of graph nodes. Throws ValueError naming the obstacle
// when factorization_obstacle() finds one.
// `variants` > 0, for stochastic L-systems (Jaeger et al. 2010, 2.1.3, stochastic case): each
// substructure (module, parameters, remaining steps) is derived in at most `variants` versions,
// each with its own draws from the generator seeded by options.seed, and every occurrence of a
// module in a successor takes one of them, drawn from the same generator. The derived plant is a
// sample of the L-system restricted to that many variants per substructure; the same seed gives
// the same graph.
SubstructureGraph derive_substructures(const LSystem& system, const DeriveOptions& options = {},
                                       int variants = 0);

SubstructureCounts count_modules(const SubstructureGraph& graph, std::size_t symbol_count);

// The explicit string (what derive() returns for the same L-system and options). Throws
// ValueError when it would exceed `module_budget` modules.
ModuleString expand(const SubstructureGraph& graph, std::size_t module_budget);

}  // namespace fspm::lsystem
