#include "experiments/adapt_model.hpp"

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <future>
#include <map>
#include <mutex>
#include <tuple>

#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"
#include "experiments/light_interception.hpp"
#include "experiments/metrics.hpp"
#include "experiments/scene_cache.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::experiments {
namespace {

namespace env = fspm::environment;
using Clock = std::chrono::steady_clock;

bool is_analysis_parameter(const std::string& name) {
  static const char* const kNames[] = {
      "skeleton_radius_m",    "min_cluster_radius_m", "gamma0",       "pruning_strength",
      "reference_percentile", "temporal_pruning",     "phototropism", "gravitropism",
      "light_directions",     "light_significance",   "light_model",  "relative_pruning"};
  for (const char* n : kNames) {
    if (name == n) return true;
  }
  return false;
}

bool parameter_flag(const ParameterValue& value, const std::string& name) {
  const std::int64_t v = parameter_integer(value, name);
  if (v != 0 && v != 1) throw ValueError(name + " must be 0 or 1");
  return v == 1;
}

// The analysis parameters of a run over the defaults; validated.
env::AnalysisParams analysis_params(const ParameterSet& parameters) {
  env::AnalysisParams p;
  for (const auto& [name, value] : parameters) {
    if (name == "skeleton_radius_m") p.skeleton_radius_m = parameter_number(value, name);
    if (name == "min_cluster_radius_m") p.min_cluster_radius_m = parameter_number(value, name);
    if (name == "gamma0") p.gamma0 = parameter_number(value, name);
    if (name == "pruning_strength") p.pruning_strength = parameter_number(value, name);
    if (name == "reference_percentile") p.reference_percentile = parameter_number(value, name);
    if (name == "phototropism") p.phototropism = parameter_number(value, name);
    if (name == "gravitropism") p.gravitropism = parameter_number(value, name);
    if (name == "light_significance") p.light_significance = parameter_number(value, name);
    if (name == "temporal_pruning") p.temporal_pruning = parameter_flag(value, name);
    if (name == "relative_pruning") p.relative_pruning = parameter_flag(value, name);
    if (name == "light_model") {
      p.light_model = env::cluster_light_model_from_name(parameter_string(value, name));
    }
    if (name == "light_directions") {
      const std::int64_t v = parameter_integer(value, name);
      if (v < 1 || v > 4096) throw ValueError("light_directions must be in [1, 4096]");
      p.light_directions = static_cast<int>(v);
    }
  }
  p.validate();
  return p;
}

using AnalysisKey = std::tuple<double, double, double, double, double, bool, double, double, int,
                               double, env::ClusterLightModel, bool>;

AnalysisKey key_of(const env::AnalysisParams& p) {
  return {p.skeleton_radius_m,    p.min_cluster_radius_m, p.gamma0,       p.pruning_strength,
          p.reference_percentile, p.temporal_pruning,     p.phototropism, p.gravitropism,
          p.light_directions,     p.light_significance,   p.light_model,  p.relative_pruning};
}

class AdaptModel final : public Model {
 public:
  AdaptModel(const std::string& tree_file, const std::string& scene_file, std::string base_dir)
      : tree_(read_tree_file(tree_file)), default_scene_(scene_file), scenes_(std::move(base_dir)) {
    if (tree_.empty()) throw ValueError("model.file: the tree is empty", tree_file);
    if (!default_scene_.empty()) scene(default_scene_);
  }

  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "scene") {
      const std::string s = parameter_string(value, name);
      if (s != "open") scene(resolve(s));
      return;
    }
    if (name == "tree_x_m" || name == "tree_y_m") {
      if (!std::isfinite(parameter_number(value, name))) {
        throw ValueError(name + " must be a finite number");
      }
      return;
    }
    if (!is_analysis_parameter(name)) {
      throw ValueError(
          "unknown parameter of model kind adapt (expected scene, tree_x_m, "
          "tree_y_m or an analysis parameter: skeleton_radius_m, "
          "min_cluster_radius_m, gamma0, pruning_strength, reference_percentile, "
          "temporal_pruning, phototropism, gravitropism, light_directions, "
          "light_significance, light_model, relative_pruning)");
    }
    analysis_params({{name, value}});
  }

  void check_setup(const ParameterSet& parameters) const override { analysis_params(parameters); }

  RunResult run(const ParameterSet& parameters, std::uint64_t /*seed*/,
                const RunContext& context) const override {
    const env::AnalysisParams params = analysis_params(parameters);
    std::string scene_path = default_scene_;
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    for (const auto& [name, value] : parameters) {
      if (name == "scene") {
        const std::string s = parameter_string(value, name);
        scene_path = s == "open" ? std::string() : resolve(s);
      }
      if (name == "tree_x_m") at.x() = parameter_number(value, name);
      if (name == "tree_y_m") at.y() = parameter_number(value, name);
    }
    const env::Scene empty;
    // The tree stays where it is; the scene moves the other way.
    const env::Scene placed = env::translated(scene_path.empty() ? empty : scene(scene_path), -at);

    RunResult result;
    const auto [analysis, analysis_seconds] = analysis_for(params, placed.sky.brightest);
    result.metrics["analysis_seconds"] = analysis_seconds;
    context.check();
    const Clock::time_point t0 = Clock::now();
    env::AdaptationResult adapted = env::adapt_tree(tree_, *analysis, placed);
    result.metrics["adapt_seconds"] = seconds_since(t0);
    result.metrics["pruned_nodes"] = static_cast<double>(adapted.pruned_nodes);
    result.metrics["tip_displacement"] = adapted.mean_tip_displacement_m;
    result.tree = env::remove_pruned(adapted.tree);
    // The tree's own leaf clusters where it has them (a grown tree), moved by the adaptation;
    // otherwise the analysis' clusters.
    std::vector<env::Sphere> clusters = leaf_cluster_spheres(*result.tree);
    if (clusters.empty()) clusters = env::cluster_spheres(adapted.clusters);
    result.metrics["light_interception"] = light_interception(placed, clusters);
    env::Scene lit = placed;
    lit.sky.directions = params.light_directions;
    add_canopy_light_metrics(lit, clusters, result.metrics);
    for (auto& [name, value] : tree_metrics(*result.tree)) result.metrics[name] = value;
    return result;
  }

 private:
  using Analysis = std::pair<std::shared_ptr<const env::TreeAnalysis>, double>;

  const env::Scene& scene(const std::string& path) const { return scenes_.get(path); }
  std::string resolve(const std::string& path) const { return scenes_.resolve(path); }

  // The analysis for these parameters, made by the first run that needs it while the others
  // wait for it (the sky the tree grew under is the scene's: the open-grown tree saw the same
  // brightest point). Its time is reported with every run that uses it.
  Analysis analysis_for(const env::AnalysisParams& params, const Eigen::Vector3d& brightest) const {
    const AnalysisKey key = key_of(params);
    const std::tuple<double, double, double> sky{brightest.x(), brightest.y(), brightest.z()};
    std::promise<Analysis> promise;
    std::shared_future<Analysis> future;
    bool mine = false;
    {
      const std::lock_guard lock(mutex_);
      auto it = analyses_.find({key, sky});
      if (it == analyses_.end()) {
        future = promise.get_future().share();
        analyses_.emplace(std::make_pair(key, sky), future);
        mine = true;
      } else {
        future = it->second;
      }
    }
    if (mine) {
      try {
        const Clock::time_point t0 = Clock::now();
        auto a = std::make_shared<const env::TreeAnalysis>(env::analyze_tree(
            tree_, params, brightest.norm() > 0 ? brightest : Eigen::Vector3d::UnitZ()));
        promise.set_value({std::move(a), seconds_since(t0)});
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return future.get();
  }

  TreeGraph tree_;
  std::string default_scene_;
  mutable std::mutex mutex_;  // guards analyses_
  SceneCache scenes_;
  mutable std::map<std::pair<AnalysisKey, std::tuple<double, double, double>>,
                   std::shared_future<Analysis>>
      analyses_;
};

}  // namespace

std::unique_ptr<Model> make_adapt_model(const std::string& tree_file, const std::string& scene_file,
                                        const std::string& base_dir) {
  return std::make_unique<AdaptModel>(tree_file, scene_file, base_dir);
}

}  // namespace fspm::experiments
