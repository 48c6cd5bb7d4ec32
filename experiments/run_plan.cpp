#include "experiments/run_plan.hpp"

#include <cmath>
#include <numeric>
#include <random>

#include "experiments/run_seed.hpp"
#include "fspm/error.hpp"

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

std::vector<std::vector<ParameterValue>> draw_samples(const Sampling& sampling) {
  const std::size_t n = sampling.samples;
  const std::size_t d = sampling.parameters.size();
  std::mt19937_64 rng(sampling.seed);
  std::vector<std::vector<double>> unit(n, std::vector<double>(d));
  if (sampling.method == SamplingMethod::kRandom) {
    for (auto& row : unit) {
      for (double& u : row) u = uniform01(rng);
    }
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
        unit[i][j] = (static_cast<double>(strata[i]) + uniform01(rng)) / static_cast<double>(n);
      }
    }
  }
  std::vector<std::vector<ParameterValue>> values(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < d; ++j) {
      values[i].push_back(map_unit(sampling.parameters[j], unit[i][j]));
    }
  }
  return values;
}

RunPlan::RunPlan(const Experiment& experiment)
    : seed_(experiment.seed), replicates_(experiment.replicates) {
  const std::size_t grid = experiment.grid_points();
  std::vector<std::vector<ParameterValue>> samples;
  if (experiment.sampling) samples = draw_samples(*experiment.sampling);
  const std::size_t per_grid = experiment.sampling ? samples.size() : 1;
  points_.reserve(grid * per_grid);
  for (std::size_t g = 0; g < grid; ++g) {
    ParameterSet base = experiment.fixed;
    // Mixed-radix digits of g, last axis fastest.
    std::size_t rest = g;
    for (std::size_t a = experiment.sweep.size(); a-- > 0;) {
      const SweepAxis& axis = experiment.sweep[a];
      base[axis.name] = axis.values[rest % axis.values.size()];
      rest /= axis.values.size();
    }
    for (std::size_t s = 0; s < per_grid; ++s) {
      ParameterSet p = base;
      if (experiment.sampling) {
        for (std::size_t j = 0; j < experiment.sampling->parameters.size(); ++j) {
          p[experiment.sampling->parameters[j].name] = samples[s][j];
        }
      }
      points_.push_back(std::move(p));
    }
  }
  runs_ = points_.size() * replicates_;
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
  spec.parameters = points_[spec.point];
  return spec;
}

}  // namespace fspm::experiments
