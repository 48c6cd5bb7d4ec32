#pragma once
// The runs of an experiment: every grid point (the product of the sweep axes, file order, last
// axis fastest) crossed with every sample of [sampling], each repeated `replicates` times.
// Run index = point * replicates + replicate; point = grid_point * samples + sample.
// The plan is lazy: it keeps the axes and the drawn samples, not the points, and computes a
// point's parameters from its index (mixed-radix digits), so a sweep of 10^7 points is planned
// at once in the memory of its axes.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/parameter_set.hpp"

namespace fspm::experiments {

struct RunSpec {
  std::size_t index = 0;
  std::size_t point = 0;
  std::size_t replicate = 0;
  std::uint64_t seed = 0;   // run_seed(experiment seed, index)
  ParameterSet parameters;  // fixed, swept and sampled
};

// The sampled values, samples x parameters, sample-major: sample i's value of parameter j (in the
// order of Sampling::parameters) at i * parameters + j. Random: each value independent; Latin
// hypercube (McKay, Beckman & Conover 1979): per parameter, one value in each of the `samples`
// equal-probability strata, strata shuffled independently per parameter.
std::vector<ParameterValue> draw_samples(const Sampling& sampling);

class RunPlan {
 public:
  // Draws the samples (MemoryLimitError when they would not fit in the memory limit).
  explicit RunPlan(const Experiment& experiment);
  std::size_t size() const { return runs_; }
  std::size_t points() const { return points_; }
  // Throws ValueError when index >= size().
  RunSpec run(std::size_t index) const;
  // Parameters of point `point` < points(), computed from its index.
  ParameterSet point_parameters(std::size_t point) const;
  std::size_t point_of(std::size_t index) const { return index / replicates_; }
  // Bytes the plan itself holds (axes and samples), independent of the number of points.
  std::size_t memory_bytes() const;

 private:
  std::uint64_t seed_ = 0;
  std::size_t replicates_ = 1;
  std::size_t runs_ = 0;
  std::size_t points_ = 0;
  std::size_t per_grid_ = 1;  // samples per grid point (1 without [sampling])
  ParameterSet fixed_;
  std::vector<SweepAxis> sweep_;
  std::vector<std::string> sampled_names_;
  std::vector<ParameterValue> samples_;  // draw_samples: samples x sampled_names_, sample-major
};

}  // namespace fspm::experiments
