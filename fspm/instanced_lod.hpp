#pragma once
// Level of detail by exploring the graph (Jaeger et al. 2010, 3.1.1): the plant is traversed
// axis by axis, order by order, so a coarser model is made by stopping at a branching order and
// by merging consecutive metamers of the same direction into one component. Applied to an
// instanced tree, substructure by substructure: each prototype is reduced once per remaining
// order budget, and a substructure that reduces to a single internode is drawn in its referrer,
// where it can merge with its neighbours. The size of the reduced plant is then counted on the
// reduced prototypes, without expanding them.
#include <cstdint>
#include <limits>

#include "fspm/instanced_tree.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

struct LevelOfDetail {
  // Nodes of a higher branching order are left out, with everything they bear; infinity: all.
  double max_order = std::numeric_limits<double>::infinity();
  // Merges an internode into its parent internode when it continues it: it starts where the
  // parent ends, in the same direction (cosine within 1e-9), with the same kind, physiological
  // age, branching order and user attributes, and nothing else (no other node, no substructure)
  // starts at that point (for other nodes: or within the parent's radius of it, where leaves
  // pushed to the axis surface start). The merged internode keeps the parent's start, birth time
  // and direction, ends where the child ends, and takes the length-weighted mean radius.
  bool merge_collinear = false;

  bool active() const { return merge_collinear || max_order < kUnlimitedOrder; }
  static constexpr double kUnlimitedOrder = std::numeric_limits<double>::infinity();
};

// The instanced tree with the level of detail applied. Its explicit expansion
// (expand_instanced_tree) is the explicit tree of `tree` cut at max_order and with the collinear
// internodes of each reduced substructure merged. Throws ValueError as check_instanced_tree.
InstancedTree reduce_instanced_tree(const InstancedTree& tree, const LevelOfDetail& lod);

// Nodes of the explicit tree an instanced tree stands for and the prototype occurrences it
// places, counted per prototype (saturating at 2^64 - 1), so a plant of 10^14 nodes is counted
// in microseconds.
struct InstancedCounts {
  std::uint64_t nodes = 0;
  std::uint64_t occurrences = 0;
};
InstancedCounts count_instanced_tree(const InstancedTree& tree);

// The level of detail applied to one explicit tree (a single prototype).
TreeGraph reduce_tree(const TreeGraph& tree, const LevelOfDetail& lod);

}  // namespace fspm
