#pragma once
// InstancedTree: a plant as prototypes placed by rigid transforms (Jaeger et al. 2010, 3.1.2).
// Each prototype is a substructure drawn once in its own frame; its children are other
// prototypes placed in that frame. Producers: GreenLab's compressed graphs
// (greenlab::reconstruct_instanced) and L-systems derived into substructures
// (lsystem::interpret_instanced); consumers: the graphics module's instanced meshes. A core type so
// that neither side depends on the other.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm {

struct InstancedTree {
  struct Child {
    std::uint32_t prototype = 0;
    // Node of the parent prototype the child grows from; kNoNode when it grows from none of them
    // (its base stands where the parent's base or an earlier sibling left the turtle).
    NodeId attach = kNoNode;
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // child frame -> parent frame
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    // Branching order added to the parent's: 1 for a lateral axis (GreenLab), the turtle's
    // bracket depth where an L-system substructure starts.
    double order = 1.0;
  };
  struct Prototype {
    TreeGraph geometry;  // node 0 is the base of the substructure; may be empty
    std::vector<Child> children;
  };
  std::vector<Prototype> prototypes;  // prototypes[0] is the root
};

// The order in which the occurrences are written to the explicit tree. Depth first: each
// occurrence followed by everything that hangs from it (the turtle's order of an L-system).
// Axis by axis: breadth first over the occurrences, oldest first (trunk, then its laterals, then
// theirs), the order of greenlab::reconstruct (Jaeger 3.1.1), so that the expansion of
// greenlab::reconstruct_instanced numbers its nodes as the explicit reconstruction does.
enum class ExpansionOrder { kDepthFirst, kAxisByAxis };

// The explicit tree the instanced tree stands for: every occurrence's geometry transformed, its
// orders offset, its user attributes copied. A child's base hangs from its attach node, or, without
// one, from the node its parent occurrence hangs from (the first node when there is none). Throws
// ValueError for a child referring to a missing prototype or node, and MemoryLimitError (through
// check_memory) or ValueError when the explicit tree would exceed `max_nodes` nodes.
TreeGraph expand_instanced_tree(const InstancedTree& tree, std::size_t max_nodes,
                                ExpansionOrder order = ExpansionOrder::kDepthFirst);

// Throws ValueError when a child refers to a prototype or attachment node that does not exist.
void check_instanced_tree(const InstancedTree& tree);

}  // namespace fspm
