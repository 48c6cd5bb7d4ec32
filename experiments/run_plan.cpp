#include "experiments/run_plan.hpp"

#include <cmath>
#include <numeric>
#include <random>

#include "experiments/run_seed.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::experiments {
namespace {

// Uniform in [0, 1) from the top 53 bits: the same numbers on every platform, unlike
// std::uniform_real_distribution whose algorithm is implementation-defined.
double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

ParameterValue map_unit(const SampledParameter& p, double u) {
  if (p.integer) {
    const double span = p.high - p.low + 1.0;
    return static_cast<std::int64_t>(std::min(p.high, p.low + std::floor(u * span)));
  }
  if (p.log_scale) {
    return std::exp(std::log(p.low) + u * (std::log(p.high) - std::log(p.low)));
  }
  return p.low + u * (p.high - p.low);
}

}  // namespace

std::vector<ParameterValue> draw_samples(const Sampling& sampling) {
  const std::size_t n = sampling.samples;
  const std::size_t d = sampling.parameters.size();
  std::mt19937_64 rng(sampling.seed);
  // Flat, sample-major: one block for millions of samples, not a vector each.
  std::vector<double> unit(n * d);
  if (sampling.method == SamplingMethod::kRandom) {
    for (double& u : unit) u = uniform01(rng);
  } else {
    std::vector<std::size_t> strata(n);
    for (std::size_t j = 0; j < d; ++j) {
      std::iota(strata.begin(), strata.end(), std::size_t{0});
      // Fisher-Yates with our own index draw, so the permutation is platform-independent.
      for (std::size_t i = n; i > 1; --i) {
        const auto k = static_cast<std::size_t>(uniform01(rng) * static_cast<double>(i));
        std::swap(strata[i - 1], strata[std::min(k, i - 1)]);
      }
      for (std::size_t i = 0; i < n; ++i) {
        unit[i * d + j] =
            (static_cast<double>(strata[i]) + uniform01(rng)) / static_cast<double>(n);
      }
    }
  }
  std::vector<ParameterValue> values;
  values.reserve(n * d);
  for (std::size_t i = 0; i < n * d; ++i) {
    values.push_back(map_unit(sampling.parameters[i % d], unit[i]));
  }
  return values;
}

RunPlan::RunPlan(const Experiment& experiment)
    : seed_(experiment.seed),
      replicates_(experiment.replicates),
      fixed_(experiment.fixed),
      sweep_(experiment.sweep) {
  if (experiment.sampling) {
    const Sampling& sampling = *experiment.sampling;
    // draw_samples holds the unit values, the strata and the values at once.
    const double cells =
        static_cast<double>(sampling.samples) * static_cast<double>(sampling.parameters.size());
    check_memory(cells * (sizeof(double) + sizeof(ParameterValue)) +
                     static_cast<double>(sampling.samples) * 2 * sizeof(std::size_t),
                 "sampling " + std::to_string(sampling.samples) + " points", experiment.path);
    samples_ = draw_samples(sampling);
    per_grid_ = sampling.samples;
    for (const SampledParameter& p : sampling.parameters) sampled_names_.push_back(p.name);
  }
  points_ = experiment.grid_points() * per_grid_;
  runs_ = points_ * replicates_;
}

ParameterSet RunPlan::point_parameters(std::size_t point) const {
  ParameterSet p = fixed_;
  // Mixed-radix digits of the grid point, last axis fastest.
  std::size_t rest = point / per_grid_;
  for (std::size_t a = sweep_.size(); a-- > 0;) {
    const SweepAxis& axis = sweep_[a];
    p[axis.name] = axis.values[rest % axis.values.size()];
    rest /= axis.values.size();
  }
  if (!samples_.empty()) {
    const std::size_t d = sampled_names_.size();
    const ParameterValue* sample = samples_.data() + (point % per_grid_) * d;
    for (std::size_t j = 0; j < d; ++j) p[sampled_names_[j]] = sample[j];
  }
  return p;
}

std::size_t RunPlan::memory_bytes() const {
  std::size_t bytes = sizeof(RunPlan);
  for (const SweepAxis& axis : sweep_) bytes += axis.values.capacity() * sizeof(ParameterValue);
  return bytes + samples_.capacity() * sizeof(ParameterValue);
}

RunSpec RunPlan::run(std::size_t index) const {
  if (index >= runs_) {
    throw ValueError("run " + std::to_string(index) + " is outside the experiment's " +
                     std::to_string(runs_) + " runs");
  }
  RunSpec spec;
  spec.index = index;
  spec.point = index / replicates_;
  spec.replicate = index % replicates_;
  spec.seed = run_seed(seed_, index);
  spec.parameters = point_parameters(spec.point);
  return spec;
}

}  // namespace fspm::experiments
