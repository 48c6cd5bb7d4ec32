#pragma once
// Comparing a recovered skeleton with the true one of a simulated scan: the constrained edit
// distance of their branching structures (chains of internodes contracted to one node each,
// topological costs), the mean distance from each true branch point (the end of a node with two
// or more children) to the nearest recovered branch point, the mean distance of the recovered
// skeleton's nodes from the true segments, and the relative error of the eq. 3.1 diameters
// against the true diameter of the nearest true internode.
#include "fspm/tree_graph.hpp"

namespace fspm::scans {

struct SkeletonComparison {
  double edit_distance = 0.0;
  std::size_t true_branches = 0;       // nodes of the true branching structure
  std::size_t recovered_branches = 0;  // nodes of the recovered one
  double branch_point_error_m = 0.0;   // mean over true branch points
  double position_error_m = 0.0;       // mean over recovered nodes
  double diameter_error = 0.0;         // mean relative error over recovered nodes
};

// One node per chain (a run of nodes without branching): start of its first node, end of its
// last, summed length, the radius of its first node.
TreeGraph branching_structure(const TreeGraph& tree);

// The ancestor-closed part of `tree` with radius above min_radius_m (the main skeleton Pirk
// compares), as a graph of its own.
TreeGraph main_skeleton(const TreeGraph& tree, double min_radius_m);

SkeletonComparison compare_skeletons(const TreeGraph& truth, const TreeGraph& recovered);

// Lateral branches of `truth` (nodes whose order exceeds their parent's) at least
// min_diameter_m thick at their base; one is recovered when `recovered` has a branch point (a
// node end with two or more children) within tolerance_m of its fork and, below that branch
// point, a segment within tolerance_m of the point half-way along the branch's axis (the chain
// of its order): the fork is found and the skeleton follows the branch from it.
struct BranchRecovery {
  std::size_t branches = 0;
  std::size_t recovered = 0;
};
BranchRecovery branch_recovery(const TreeGraph& truth, const TreeGraph& recovered,
                               double min_diameter_m, double tolerance_m);

}  // namespace fspm::scans
