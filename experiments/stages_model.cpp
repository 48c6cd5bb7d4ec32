#include "experiments/stages_model.hpp"

#include <chrono>
#include <cmath>
#include <future>
#include <map>
#include <mutex>
#include <tuple>

#include "experiments/metrics.hpp"
#include "fspm/tree_file.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::experiments {
namespace {

using Clock = std::chrono::steady_clock;

// A stage time and its seasonal remapping: what a run asks of its developmental model.
struct StageRequest {
  double t = 1.0;
  int season_years = 0;
};

// The analysis parameters of a run over the defaults; validated.
stages::StagesParams stages_params(const ParameterSet& parameters) {
  stages::StagesParams p;
  for (const auto& [name, value] : parameters) {
    if (name == "continuation") {
      p.continuation = stages::continuation_from_name(parameter_string(value, name));
    }
    if (name == "rigid_tip_count") {
      const std::int64_t v = parameter_integer(value, name);
      if (v < 1 || v > 1'000'000) throw ValueError("rigid_tip_count must be in [1, 1000000]");
      p.rigid_tip_count = static_cast<int>(v);
    }
    if (name == "pipe_exponent") p.pipe_exponent = parameter_number(value, name);
    if (name == "same_level_tolerance") p.same_level_tolerance = parameter_number(value, name);
    if (name == "added") {
      const std::int64_t v = parameter_integer(value, name);
      if (v != 0 && v != 1) throw ValueError("added must be 0 or 1");
      p.added.enabled = v == 1;
    }
    if (name == "added_gamma") p.added.gamma = parameter_number(value, name);
  }
  p.validate();
  return p;
}

StageRequest stage_request(const ParameterSet& parameters) {
  StageRequest r;
  for (const auto& [name, value] : parameters) {
    if (name == "t") r.t = parameter_number(value, name);
    if (name == "season_years") {
      const std::int64_t v = parameter_integer(value, name);
      if (v < 0 || v > 1000) throw ValueError("season_years must be in [0, 1000]");
      r.season_years = static_cast<int>(v);
    }
  }
  if (!(r.t >= 0.0 && r.t <= 1.0)) throw ValueError("t must be in [0, 1]");
  return r;
}

using AnalysisKey = std::tuple<stages::Continuation, int, double, double, bool, double>;

AnalysisKey key_of(const stages::StagesParams& p) {
  return {p.continuation,         p.rigid_tip_count, p.pipe_exponent,
          p.same_level_tolerance, p.added.enabled,   p.added.gamma};
}

// One analysed tree; stage() reuses the model's buffers, so runs sharing it take turns (a
// stage costs about a millisecond, far less than a run's bookkeeping).
struct SharedModel {
  explicit SharedModel(const TreeGraph& tree, const stages::StagesParams& params)
      : model(tree, params) {}
  stages::DevelopmentalModel model;
  std::mutex mutex;
};

class StagesModel final : public Model {
 public:
  explicit StagesModel(const std::string& tree_file) : tree_(read_tree_file(tree_file)) {
    if (tree_.empty()) throw ValueError("model.file: the tree is empty", tree_file);
  }

  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "t" || name == "season_years") {
      stage_request({{name, value}});
      return;
    }
    if (name != "continuation" && name != "rigid_tip_count" && name != "pipe_exponent" &&
        name != "same_level_tolerance" && name != "added" && name != "added_gamma") {
      throw ValueError(
          "unknown parameter of model kind stages (expected t, season_years, continuation, "
          "rigid_tip_count, pipe_exponent, same_level_tolerance, added or added_gamma)");
    }
    stages_params({{name, value}});
  }

  void check_setup(const ParameterSet& parameters) const override {
    stages_params(parameters);
    stage_request(parameters);
  }

  RunResult run(const ParameterSet& parameters, std::uint64_t /*seed*/,
                const RunContext& context) const override {
    const StageRequest request = stage_request(parameters);
    const auto [shared, analysis_seconds] = model_for(stages_params(parameters));
    context.check();
    RunResult result;
    result.metrics["analysis_seconds"] = analysis_seconds;
    const double t = request.season_years > 0
                         ? stages::seasonal_time(request.t, request.season_years)
                         : request.t;
    TreeGraph stage;
    const Clock::time_point t0 = Clock::now();
    {
      const std::lock_guard lock(shared->mutex);
      shared->model.stage(t, stage);
    }
    result.metrics["stage_seconds"] = seconds_since(t0);
    for (auto& [name, value] : tree_metrics(stage)) result.metrics[name] = value;
    result.tree = std::move(stage);
    return result;
  }

 private:
  using Analysis = std::pair<std::shared_ptr<SharedModel>, double>;

  // The model for these parameters, analysed by the first run that needs it while the others
  // wait for it; its time is reported with every run that uses it.
  Analysis model_for(const stages::StagesParams& params) const {
    std::promise<Analysis> promise;
    std::shared_future<Analysis> future;
    bool mine = false;
    {
      const std::lock_guard lock(mutex_);
      auto [it, inserted] = models_.try_emplace(key_of(params));
      if (inserted) it->second = promise.get_future().share();
      future = it->second;
      mine = inserted;
    }
    if (mine) {
      try {
        const Clock::time_point t0 = Clock::now();
        auto model = std::make_shared<SharedModel>(tree_, params);
        promise.set_value({std::move(model), seconds_since(t0)});
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return future.get();
  }

  TreeGraph tree_;
  mutable std::mutex mutex_;  // guards models_
  mutable std::map<AnalysisKey, std::shared_future<Analysis>> models_;
};

}  // namespace

std::unique_ptr<Model> make_stages_model(const std::string& tree_file) {
  return std::make_unique<StagesModel>(tree_file);
}

}  // namespace fspm::experiments
