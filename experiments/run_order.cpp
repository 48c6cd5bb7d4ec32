#include "experiments/run_order.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace fspm::experiments {

std::vector<std::size_t> longest_first(const RunPlan& plan, const Model& model,
                                       std::vector<std::size_t> pending,
                                       const std::atomic<bool>* interrupt) {
  // Replicates share their point's parameters: one estimate per point.
  std::unordered_map<std::size_t, double> by_point;
  std::vector<double> cost(pending.size());
  for (std::size_t k = 0; k < pending.size(); ++k) {
    if (interrupt != nullptr && k % 1024 == 0 && interrupt->load()) return pending;
    const std::size_t point = plan.point_of(pending[k]);
    auto it = by_point.find(point);
    if (it == by_point.end()) {
      const double c = model.cost_estimate(plan.point_parameters(point));
      it = by_point.emplace(point, std::isfinite(c) && c > 0.0 ? c : 0.0).first;
    }
    cost[k] = it->second;
  }
  std::vector<std::size_t> order(pending.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return cost[a] > cost[b] || (cost[a] == cost[b] && pending[a] < pending[b]);
  });
  std::vector<std::size_t> sorted(pending.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = pending[order[k]];
  return sorted;
}

}  // namespace fspm::experiments
