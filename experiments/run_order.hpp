#pragma once
// The order in which the runners hand out pending runs: longest processing time first (Graham
// 1969), by the model's cost estimate, ties in run index order. With dynamic scheduling this
// bounds the finish time by 4/3 of the optimum instead of leaving the longest runs (often the
// last grid points: the oldest trees, the most steps) to one worker at the end. The order never
// changes results: a run's parameters and seed depend only on its index.
#include <atomic>
#include <cstddef>
#include <vector>

#include "experiments/model.hpp"
#include "experiments/run_plan.hpp"

namespace fspm::experiments {

// Above this many pending runs the order is left as it is: estimating and sorting would delay the
// start by seconds (10^7 runs), and with that many runs per worker any order finishes within a
// fraction of one run of the optimum, which is what longest-first is for.
inline constexpr std::size_t kLongestFirstLimit = 1'000'000;

// `pending` (run indices) sorted by descending Model::cost_estimate of their point's parameters,
// stable; a non-finite or negative estimate counts as 0. When `interrupt` becomes true while the
// estimates are computed (a long plan), `pending` is returned unsorted at once; more than
// kLongestFirstLimit runs are returned as given.
std::vector<std::size_t> longest_first(const RunPlan& plan, const Model& model,
                                       std::vector<std::size_t> pending,
                                       const std::atomic<bool>* interrupt = nullptr);

}  // namespace fspm::experiments
