// Both assignment solvers against an exhaustive minimum over all partial matchings.
#include "fspm/assignment.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <random>

#include "fspm/error.hpp"

namespace fspm {
namespace {

double brute_force(const std::vector<double>& pair, std::size_t rows, std::size_t cols,
                   const std::vector<double>& ra, const std::vector<double>& ca) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<char> used(cols, 0);
  std::function<void(std::size_t, double)> go = [&](std::size_t r, double partial) {
    if (r == rows) {
      double c = partial;
      for (std::size_t k = 0; k < cols; ++k) c += used[k] ? 0.0 : ca[k];
      best = std::min(best, c);
      return;
    }
    go(r + 1, partial + ra[r]);
    for (std::size_t k = 0; k < cols; ++k) {
      if (used[k]) continue;
      used[k] = 1;
      go(r + 1, partial + pair[r * cols + k]);
      used[k] = 0;
    }
  };
  go(0, 0.0);
  return best;
}

double cost_of(const PartialAssignment& a, const std::vector<double>& pair, std::size_t cols,
               const std::vector<double>& ra, const std::vector<double>& ca) {
  double c = 0.0;
  std::vector<char> used(cols, 0);
  for (std::size_t r = 0; r < a.row_to_col.size(); ++r) {
    const int k = a.row_to_col[r];
    if (k < 0) {
      c += ra[r];
    } else {
      EXPECT_FALSE(used[static_cast<std::size_t>(k)]);
      used[static_cast<std::size_t>(k)] = 1;
      c += pair[r * cols + static_cast<std::size_t>(k)];
    }
  }
  for (std::size_t k = 0; k < cols; ++k) c += used[k] ? 0.0 : ca[k];
  return c;
}

TEST(Assignment, BothSolversMatchBruteForce) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t rows = std::uniform_int_distribution<std::size_t>(0, 6)(rng);
    const std::size_t cols = std::uniform_int_distribution<std::size_t>(0, 6)(rng);
    std::vector<double> pair(rows * cols), ra(rows), ca(cols);
    for (auto& v : pair) v = u(rng);
    for (auto& v : ra) v = u(rng) * 0.5;
    for (auto& v : ca) v = u(rng) * 0.5;
    const double expected = brute_force(pair, rows, cols, ra, ca);
    for (const auto solver : {AssignmentSolver::kHungarian, AssignmentSolver::kMinCostFlow}) {
      const auto got = solve_partial_assignment(pair, rows, cols, ra, ca, solver);
      EXPECT_NEAR(got.cost, expected, 1e-9) << assignment_solver_name(solver) << " " << trial;
      EXPECT_NEAR(cost_of(got, pair, cols, ra, ca), expected, 1e-9);
    }
  }
}

TEST(Assignment, ClassicThreeByThree) {
  // Textbook matrix with optimum 5 (1 + 2 + 2), leaving nothing alone (alone is expensive).
  const std::vector<double> pair{4, 1, 3, 2, 0, 5, 3, 2, 2};
  const std::vector<double> alone{100, 100, 100};
  for (const auto solver : {AssignmentSolver::kHungarian, AssignmentSolver::kMinCostFlow}) {
    const auto got = solve_partial_assignment(pair, 3, 3, alone, alone, solver);
    EXPECT_DOUBLE_EQ(got.cost, 5.0);
    EXPECT_EQ(got.row_to_col, (std::vector<int>{1, 0, 2}));
  }
}

TEST(Assignment, RejectsNegativeCosts) {
  const std::vector<double> pair{-1.0}, alone{1.0};
  EXPECT_THROW(solve_partial_assignment(pair, 1, 1, alone, alone), ValueError);
  EXPECT_THROW(assignment_solver_from_name("simplex"), ValueError);
}

}  // namespace
}  // namespace fspm
