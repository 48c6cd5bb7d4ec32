#include "experiments/run_order.hpp"

#include <algorithm>
#include <cmath>

namespace fspm::experiments {

std::vector<std::size_t> longest_first(const RunPlan& plan, const Model& model,
                                       std::vector<std::size_t> pending,
                                       const std::atomic<bool>* interrupt) {
  if (pending.size() > kLongestFirstLimit) return pending;
  // Replicates share their point's parameters and are adjacent in the run order (index = point
  // x replicates + replicate): one estimate per point, remembered until the next point.
  std::vector<double> cost(pending.size());
  std::size_t last_point = 0;
  double last_cost = 0.0;
  bool have_last = false;
  for (std::size_t k = 0; k < pending.size(); ++k) {
    if (interrupt != nullptr && k % 1024 == 0 && interrupt->load()) return pending;
    const std::size_t point = plan.point_of(pending[k]);
    if (!have_last || point != last_point) {
      const double c = model.cost_estimate(plan.point_parameters(point));
      last_cost = std::isfinite(c) && c > 0.0 ? c : 0.0;
      last_point = point;
      have_last = true;
    }
    cost[k] = last_cost;
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
