#pragma once
// Constrained edit distance between rooted unordered trees (Zhang 1996; Ferraro and Godin 2000;
// Pirk sec. 4.5, eq. 4.15-4.22): the cheapest mapping between the nodes of two trees that is
// one-to-one (eq. 4.19), keeps ancestors (eq. 4.20) and keeps disjoint subtrees disjoint (eq.
// 4.21), where a matched pair costs a relabel and an unmatched node a delete (tree A) or an
// insert (tree B). Computed exactly by Zhang's dynamic programme over post-ordered nodes, with
// the two child forests of each pair matched by a minimum-cost bipartite assignment.
//
// Why relabel(a, b) <= delete(a) + insert(b) is required: the recurrences only consider mappings
// in which, for every pair of subtrees (T_A[i], T_B[j]) they compare, some node of one is matched
// to some node of the other (a leaf j, for instance, is either matched or T_A[i] maps inside it).
// The mapping that deletes all of T_A[i] and inserts all of T_B[j] is never enumerated. With the
// bound, matching the two roots instead costs relabel(i, j) <= delete(i) + insert(j), so that
// mapping is never cheaper and dropping it loses nothing; without the bound the programme can
// return more than the true minimum. Every built-in model satisfies it (|x - y| <= |x| + |y|);
// a custom model that breaks it is rejected with ValueError.
//
// Time O(|A| |B| (deg A + deg B)^3) in the worst case, close to O(|A| |B|) on plant trees whose
// nodes have few children. Memory: rows of |B| values for the nodes of A whose parent is still
// pending (children visited in Sethi-Ullman order keep that few); with the mapping requested,
// 6 bytes per node pair more for the traceback.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fspm/assignment.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

struct EditDistanceOptions {
  EditCostKind cost = EditCostKind::kTopological;
  std::vector<std::string> attributes;  // empty: default_edit_attributes(cost)
  // Compare only the main skeleton: nodes whose radius is above this and whose ancestors all are
  // (Pirk compares the main branching structure above a thickness threshold).
  std::optional<double> main_skeleton_radius_m;
  AssignmentSolver solver = AssignmentSolver::kHungarian;
  bool with_mapping = false;
};

struct EditDistanceResult {
  double distance = 0.0;
  // distance / (deletion_cost_a + insertion_cost_b), in [0, 1]; see normalized_edit_distance.
  double normalized = 0.0;
  // Cost of deleting every compared node of A, and of inserting every compared node of B: the
  // cost of the empty mapping, the largest the distance can be.
  double deletion_cost_a = 0.0;
  double insertion_cost_b = 0.0;
  std::size_t nodes_a = 0;  // nodes compared (all, or the main skeleton)
  std::size_t nodes_b = 0;
  // Matched (node of A, node of B) pairs, by node id, sorted by the node of A; empty unless
  // with_mapping was set.
  std::vector<std::pair<NodeId, NodeId>> mapping;
};

// The distance on a scale from 0 (identical trees) to 1 (nothing in common): divided by the cost
// of the empty mapping, deleting all of A and inserting all of B (one of the normalisations
// Ferraro and Godin 2000 discuss). The distance never exceeds that cost: matching the two roots
// and deleting and inserting the rest is a valid mapping that costs at most as much, because
// relabel(a, b) <= delete(a) + insert(b). 0 when both costs are 0 (then so is the distance);
// clamped to [0, 1] against rounding.
double normalized_edit_distance(double distance, double deletion_cost_a, double insertion_cost_b);

// Nodes of the main skeleton: radius > min_radius_m and every ancestor too (empty when the root
// is below the threshold). In id order.
std::vector<NodeId> main_skeleton_nodes(const TreeGraph& tree, double min_radius_m);

// Distance with a built-in cost model (options.cost, options.attributes).
EditDistanceResult constrained_edit_distance(const TreeGraph& a, const TreeGraph& b,
                                             const EditDistanceOptions& options = {});

// Distance with a custom cost model; options.cost and options.attributes are ignored.
EditDistanceResult constrained_edit_distance(const TreeGraph& a, const TreeGraph& b,
                                             const EditCostModel& costs,
                                             const EditDistanceOptions& options = {});

}  // namespace fspm
