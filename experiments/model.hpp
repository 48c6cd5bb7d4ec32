#pragma once
// The small interface between the runner and a model: given the parameters of one run and its
// seed, produce metrics (and optionally the tree). Models must allow concurrent run() calls.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "experiments/parameter_set.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::experiments {

// Thrown by RunContext::check when the run's time limit has passed or the sweep was interrupted.
class RunStopped : public Error {
 public:
  RunStopped(const std::string& message, bool timed_out) : Error(message), timed_out_(timed_out) {}
  bool timed_out() const { return timed_out_; }

 private:
  bool timed_out_;
};

// What a run may consult while it works: models call check() between steps so that a run over
// its time limit, or a sweep stopped with Ctrl-C, ends promptly.
class RunContext {
 public:
  using Clock = std::chrono::steady_clock;
  RunContext() = default;
  RunContext(std::optional<Clock::time_point> deadline, const std::atomic<bool>* interrupted)
      : deadline_(deadline), interrupted_(interrupted) {}
  // Throws RunStopped when the deadline passed or the sweep is being interrupted.
  void check() const;
  bool has_deadline() const { return deadline_.has_value(); }

 private:
  std::optional<Clock::time_point> deadline_;
  const std::atomic<bool>* interrupted_ = nullptr;
};

struct RunResult {
  std::map<std::string, double> metrics;  // by metric name (experiments/metrics.hpp)
  std::optional<TreeGraph> tree;          // when the model builds an explicit tree
};

class Model {
 public:
  virtual ~Model() = default;
  // Throws ValueError naming `name` when the model has no parameter of that name, or `value` is
  // not acceptable for it. Called for every parameter before any run starts.
  virtual void check_parameter(const std::string& name, const ParameterValue& value) const = 0;
  // Checks what can be checked without running, with the parameters of the first run (parses the
  // model file, ...). Throws the model's own errors.
  virtual void check_setup(const ParameterSet& /*parameters*/) const {}
  // One run. Throws on failure (the runner records the message and goes on).
  virtual RunResult run(const ParameterSet& parameters, std::uint64_t seed,
                        const RunContext& context) const = 0;
  // Relative cost of a run with these parameters, for scheduling only: the runners hand out the
  // costliest runs first (longest processing time first, Graham 1969), so that no long run is
  // left for the end while the other workers idle. Any positive scale, only the order matters;
  // must not throw. Default: every run costs the same (grid order).
  virtual double cost_estimate(const ParameterSet& /*parameters*/) const { return 1.0; }
};

}  // namespace fspm::experiments
