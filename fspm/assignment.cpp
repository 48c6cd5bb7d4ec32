#include "fspm/assignment.hpp"

#include <algorithm>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/successive_shortest_path_nonnegative_weights.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "fspm/error.hpp"

namespace fspm {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void check_costs(std::span<const double> costs, const char* what) {
  for (const double c : costs) {
    if (!std::isfinite(c) || c < 0.0) {
      throw ValueError(std::string("assignment: ") + what +
                       " must be finite and non-negative, found " + std::to_string(c));
    }
  }
}

PartialAssignment solve_hungarian(std::span<const double> pair_cost, std::size_t rows,
                                  std::size_t cols, std::span<const double> row_alone,
                                  std::span<const double> col_alone) {
  PartialAssignment result;
  result.row_to_col.assign(rows, -1);
  double base = 0.0;
  for (const double c : row_alone) base += c;
  for (const double c : col_alone) base += c;
  result.cost = base;
  if (rows == 0 || cols == 0) return result;
  // Work on the smaller side as rows; gain = pair - alone, clamped at 0 (unmatched is free).
  const bool transposed = rows > cols;
  const std::size_t n = transposed ? cols : rows;
  const std::size_t m = transposed ? rows : cols;
  std::vector<double> gain(n * m);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      const double g = std::min(0.0, pair_cost[r * cols + c] - row_alone[r] - col_alone[c]);
      gain[transposed ? c * m + r : r * m + c] = g;
    }
  }
  std::vector<int> assign(n);
  HungarianWorkspace work;
  result.cost = base + work.solve(gain.data(), n, m, assign.data());
  for (std::size_t k = 0; k < n; ++k) {
    const auto r = transposed ? static_cast<std::size_t>(assign[k]) : k;
    const auto c = transposed ? k : static_cast<std::size_t>(assign[k]);
    if (pair_cost[r * cols + c] <= row_alone[r] + col_alone[c]) {
      result.row_to_col[r] = static_cast<int>(c);
    }
  }
  return result;
}

// Min-cost flow network: source -> each row -> (each column | "row alone") -> sink, and
// source -> "column alone" -> each column, with "column alone" -> "row alone" carrying the
// matched units. Every unit of rows + cols must reach the sink, so the minimum-cost maximum flow
// is the minimum partial assignment. Boost's Dijkstra step rejects the tiny negative reduced costs
// that double rounding produces, so costs are scaled to whole numbers (2^40 units for the largest
// cost, relative rounding below 1e-12), which doubles add exactly (path sums stay below 2^53), and
// the cost is then summed from the original doubles. Doubles rather than 64-bit integers because
// Boost adds the "infinite" distances of unreached vertices, which overflows integers.
PartialAssignment solve_min_cost_flow(std::span<const double> pair_cost, std::size_t rows,
                                      std::size_t cols, std::span<const double> row_alone,
                                      std::span<const double> col_alone) {
  using Traits = boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS>;
  using Graph = boost::adjacency_list<
      boost::vecS, boost::vecS, boost::directedS, boost::no_property,
      boost::property<
          boost::edge_capacity_t, long,
          boost::property<boost::edge_residual_capacity_t, long,
                          boost::property<boost::edge_reverse_t, Traits::edge_descriptor,
                                          boost::property<boost::edge_weight_t, double>>>>>;
  using Edge = Traits::edge_descriptor;
  const std::size_t source = 0, sink = 1, col_alone_node = 2, row_alone_node = 3, first_row = 4;
  const std::size_t first_col = first_row + rows;
  Graph g(first_col + cols);
  auto capacity = boost::get(boost::edge_capacity, g);
  auto reverse = boost::get(boost::edge_reverse, g);
  auto weight = boost::get(boost::edge_weight, g);
  double largest = 0.0;
  for (const auto* costs : {&pair_cost, &row_alone, &col_alone}) {
    for (const double c : *costs) largest = std::max(largest, c);
  }
  const double scale = largest > 0.0 ? std::ldexp(1.0, 40 - std::ilogb(largest)) : 1.0;
  auto add = [&](std::size_t from, std::size_t to, long cap, double real_cost) {
    const double cost = std::round(real_cost * scale);
    const Edge e = boost::add_edge(from, to, g).first;
    const Edge back = boost::add_edge(to, from, g).first;
    capacity[e] = cap;
    capacity[back] = 0;
    weight[e] = cost;
    weight[back] = -cost;
    reverse[e] = back;
    reverse[back] = e;
    return e;
  };
  std::vector<Edge> pair_edges(rows * cols);
  for (std::size_t r = 0; r < rows; ++r) {
    add(source, first_row + r, 1, 0.0);
    add(first_row + r, row_alone_node, 1, row_alone[r]);
    for (std::size_t c = 0; c < cols; ++c) {
      pair_edges[r * cols + c] = add(first_row + r, first_col + c, 1, pair_cost[r * cols + c]);
    }
  }
  for (std::size_t c = 0; c < cols; ++c) {
    add(col_alone_node, first_col + c, 1, col_alone[c]);
    add(first_col + c, sink, 1, 0.0);
  }
  add(source, col_alone_node, static_cast<long>(cols), 0.0);
  add(row_alone_node, sink, static_cast<long>(rows), 0.0);
  add(col_alone_node, row_alone_node, static_cast<long>(std::min(rows, cols)), 0.0);

  boost::successive_shortest_path_nonnegative_weights(g, source, sink);
  PartialAssignment result;
  auto residual = boost::get(boost::edge_residual_capacity, g);
  result.row_to_col.assign(rows, -1);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      if (residual[pair_edges[r * cols + c]] == 0) result.row_to_col[r] = static_cast<int>(c);
    }
  }
  std::vector<char> col_used(cols, 0);
  for (std::size_t r = 0; r < rows; ++r) {
    const int c = result.row_to_col[r];
    if (c < 0) {
      result.cost += row_alone[r];
    } else {
      col_used[static_cast<std::size_t>(c)] = 1;
      result.cost += pair_cost[r * cols + static_cast<std::size_t>(c)];
    }
  }
  for (std::size_t c = 0; c < cols; ++c) result.cost += col_used[c] ? 0.0 : col_alone[c];
  return result;
}

}  // namespace

std::string_view assignment_solver_name(AssignmentSolver solver) {
  return kAssignmentSolverNames.name(solver);
}

AssignmentSolver assignment_solver_from_name(std::string_view name) {
  return kAssignmentSolverNames.from_name(name);
}

PartialAssignment solve_partial_assignment(std::span<const double> pair_cost, std::size_t rows,
                                           std::size_t cols, std::span<const double> row_alone,
                                           std::span<const double> col_alone,
                                           AssignmentSolver solver) {
  if (pair_cost.size() != rows * cols || row_alone.size() != rows || col_alone.size() != cols) {
    throw ValueError("assignment: cost sizes do not match " + std::to_string(rows) + " rows and " +
                     std::to_string(cols) + " columns");
  }
  check_costs(pair_cost, "pair costs");
  check_costs(row_alone, "row costs");
  check_costs(col_alone, "column costs");
  return solver == AssignmentSolver::kHungarian
             ? solve_hungarian(pair_cost, rows, cols, row_alone, col_alone)
             : solve_min_cost_flow(pair_cost, rows, cols, row_alone, col_alone);
}

// Shortest augmenting paths with row and column potentials (Kuhn-Munkres in the O(n^2 m) form of
// Jonker and Volgenant): rows are added one by one, each by a Dijkstra-like search over reduced
// costs. Index 0 is a virtual column that holds the row being inserted.
double HungarianWorkspace::solve(const double* gain, std::size_t rows, std::size_t cols,
                                 int* row_to_col) {
  const std::size_t n = rows, m = cols;
  u_.assign(n + 1, 0.0);
  v_.assign(m + 1, 0.0);
  col_owner_.assign(m + 1, 0);
  way_.assign(m + 1, 0);
  min_slack_.resize(m + 1);
  used_.resize(m + 1);
  for (std::size_t i = 1; i <= n; ++i) {
    col_owner_[0] = static_cast<int>(i);
    std::size_t j0 = 0;
    std::fill(min_slack_.begin(), min_slack_.end(), kInf);
    std::fill(used_.begin(), used_.end(), 0);
    do {
      used_[j0] = 1;
      const auto i0 = static_cast<std::size_t>(col_owner_[j0]);
      double delta = kInf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= m; ++j) {
        if (used_[j]) continue;
        const double cur = gain[(i0 - 1) * m + (j - 1)] - u_[i0] - v_[j];
        if (cur < min_slack_[j]) {
          min_slack_[j] = cur;
          way_[j] = static_cast<int>(j0);
        }
        if (min_slack_[j] < delta) {
          delta = min_slack_[j];
          j1 = j;
        }
      }
      for (std::size_t j = 0; j <= m; ++j) {
        if (used_[j]) {
          u_[static_cast<std::size_t>(col_owner_[j])] += delta;
          v_[j] -= delta;
        } else {
          min_slack_[j] -= delta;
        }
      }
      j0 = j1;
    } while (col_owner_[j0] != 0);
    do {
      const auto j1 = static_cast<std::size_t>(way_[j0]);
      col_owner_[j0] = col_owner_[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  double total = 0.0;
  for (std::size_t j = 1; j <= m; ++j) {
    if (col_owner_[j] != 0) {
      const auto r = static_cast<std::size_t>(col_owner_[j] - 1);
      row_to_col[r] = static_cast<int>(j - 1);
      total += gain[r * m + (j - 1)];
    }
  }
  return total;
}

}  // namespace fspm
