#pragma once
// Minimum-cost partial assignment between two small sets, as the constrained edit distance needs
// it to match two child forests (Zhang 1996, restricted mapping; Pirk eq. 4.22). Two solvers:
// a shortest-augmenting-path Hungarian method (Jonker-Volgenant style, O(n^2 m)) and Boost.Graph's
// successive-shortest-path min-cost flow. They give the same minimum; the Hungarian one is faster
// on the small matrices of plant trees and is the default.
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "fspm/name_table.hpp"

namespace fspm {

enum class AssignmentSolver { kHungarian, kMinCostFlow };

inline constexpr NameTable<AssignmentSolver, 2> kAssignmentSolverNames{
    "assignment solver",
    {{AssignmentSolver::kHungarian, "hungarian", "Hungarian method, O(n^3)"},
     {AssignmentSolver::kMinCostFlow, "min-cost-flow", "successive shortest paths"}}};
inline constexpr auto kAssignmentSolvers = kAssignmentSolverNames.values();

// "hungarian", "min-cost-flow".
std::string_view assignment_solver_name(AssignmentSolver solver);
// Inverse of assignment_solver_name; throws ValueError on an unknown name.
AssignmentSolver assignment_solver_from_name(std::string_view name);

struct PartialAssignment {
  double cost = 0.0;
  std::vector<int> row_to_col;  // matched column of each row, -1 when the row stays unmatched
};

// Minimum over partial one-to-one matchings s between rows and columns of
//   sum_{(r,c) in s} pair_cost[r*cols+c] + sum_{r unmatched} row_alone[r]
//                                        + sum_{c unmatched} col_alone[c].
// All costs must be finite and non-negative (ValueError otherwise). A pair is reported matched
// when its cost does not exceed leaving both alone.
PartialAssignment solve_partial_assignment(std::span<const double> pair_cost, std::size_t rows,
                                           std::size_t cols, std::span<const double> row_alone,
                                           std::span<const double> col_alone,
                                           AssignmentSolver solver = AssignmentSolver::kHungarian);

// Reusable Hungarian solver for the hot loop of the edit distance: no allocation after warm-up.
// Solves min over full assignments of the rows (rows <= cols) of sum gain[r*cols + c], where every
// gain is <= 0 (a pair's cost minus the cost of leaving both alone, clamped at 0 so that "stay
// unmatched" is free). Writes the column of each row into row_to_col and returns the minimum.
class HungarianWorkspace {
 public:
  double solve(const double* gain, std::size_t rows, std::size_t cols, int* row_to_col);

 private:
  std::vector<double> u_, v_, min_slack_;
  std::vector<int> col_owner_, way_;
  std::vector<char> used_;
};

}  // namespace fspm
