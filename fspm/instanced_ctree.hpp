#pragma once
// Instanced trees (drawn L-systems) as compressed tree graphs with turtle geometry (.ctree
// version 2), and back. Each prototype becomes a group record, which stands for the substructure
// and draws nothing, followed by one record per node of its geometry: a node's successor is its
// first child in the prototype, its axillaries its other children and then the groups of the
// prototypes placed at it, each with its rigid placement (Jaeger et al. 2010, 3.1.2). The
// prototypes that grow from no node of their parent are members of the parent's group, so they
// hang from what the parent hangs from, as in expand_instanced_tree. Every record then stands
// for one node (or one substructure) shared by all occurrences, and the multiplicities count
// them.
#include <cstdint>
#include <limits>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_tree.hpp"

namespace fspm {

// The graph of `tree` (InstancedTree::prototypes[0] the root): birth dates 0, physiological age
// 1, final age 0. Throws ValueError for a child referring to a missing prototype or node.
CompressedTreeGraph compress_instanced_tree(const InstancedTree& tree);

struct CtreeInstancingOptions {
  double max_birth = std::numeric_limits<double>::infinity();  // records born later left out
  bool leaves = true;
  bool flowers = true;
};

// The instanced tree a graph with geometry stands for: one prototype per group record (the root
// first), holding the organ records it bears in its frame. Records left out by `options` are
// left out with everything they bear. Throws ValueError when the graph has no geometry or breaks
// its rules (CompressedTreeGraph::validate).
InstancedTree instanced_tree_of(const CompressedTreeGraph& graph,
                                const CtreeInstancingOptions& options = {});

// Organ records (internodes, leaves, flowers) of the explicit plant: the sum of the
// multiplicities of the records that are not groups (saturating at 2^64 - 1).
std::uint64_t geometry_organ_count(const CompressedTreeGraph& graph);

}  // namespace fspm
