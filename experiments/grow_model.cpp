#include "experiments/grow_model.hpp"

#include <toml++/toml.h>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>

#include "environment/growth_model.hpp"
#include "environment/growth_params.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/sky_distribution.hpp"
#include "environment/tree_analysis.hpp"
#include "experiments/grow_set.hpp"
#include "experiments/light_interception.hpp"
#include "experiments/metrics.hpp"
#include "experiments/scene_cache.hpp"
#include "fspm/input_file.hpp"
#include "fspm/toml_text.hpp"

namespace fspm::experiments {
namespace {

namespace env = fspm::environment;
using Clock = std::chrono::steady_clock;

// The scene without its obstacles: the same sky and ground, so that set O differs from G only by
// what the obstacles do.
env::Scene open_version(const env::Scene& scene) {
  env::Scene open;
  open.sky = scene.sky;
  open.ground = scene.ground;
  return open;
}

// The `set` parameter's value as a set; throws ValueError for another value.
GrowSet grow_set(const ParameterValue& value) {
  if (const std::optional<GrowSet> set = find_grow_set(parameter_string(value, "set"))) return *set;
  throw ValueError("set must be \"O\", \"G\" or \"T\"");
}

class GrowModel final : public Model {
 public:
  GrowModel(const std::string& params_file, const std::string& scene_file, std::string base_dir)
      : base_text_(params_file.empty() ? std::string() : read_input_file(params_file)),
        base_name_(params_file.empty() ? std::string("<grow parameters>") : params_file),
        default_scene_(scene_file),
        scenes_(std::move(base_dir)) {
    env::parse_growth_params(base_text_, base_name_);  // report a bad file before any run
    if (!default_scene_.empty()) scene(default_scene_);
  }

  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    if (name == "set") {
      grow_set(value);
      return;
    }
    if (name == "scene") {
      const std::string s = parameter_string(value, name);
      if (s != "open") scene(resolve(s));
      return;
    }
    if (name == "measure_regrowth") {
      parameter_integer(value, name);
      return;
    }
    if (name == "adapt_light_model") {
      env::cluster_light_model_from_name(parameter_string(value, name));
      return;
    }
    if (name == "preset_tropisms") {  // needs a preset: the whole set is checked by check_setup
      env::tropism_pairing_from_name(parameter_string(value, name));
      return;
    }
    growth_params({{name, value}}, 1);
  }

  void check_setup(const ParameterSet& parameters) const override { growth_params(parameters, 1); }

  // Run time grows about e^(years / 4) (buds multiply until the space fills: x11 per decade on
  // the adapted-versus-grown experiment, Release, 10 to 30 years); a tree beside obstacles
  // grows a little less (set G about 0.6 of set O's time there), set T grows in the open, then
  // adapts (about 1.0).
  double cost_estimate(const ParameterSet& parameters) const override {
    try {
      const double years = growth_params(parameters, 1).years;
      double factor = 1.0;
      if (const auto it = parameters.find("set"); it != parameters.end()) {
        factor = grow_set(it->second) == GrowSet::kBesideObstacles ? 0.6 : 1.0;
      }
      return factor * std::exp(0.25 * std::min(years, 2000.0));
    } catch (const std::exception&) {
      return 1.0;
    }
  }

  RunResult run(const ParameterSet& parameters, std::uint64_t seed,
                const RunContext& context) const override {
    const env::GrowthParams params = growth_params(parameters, seed);
    GrowSet set = GrowSet::kBesideObstacles;
    std::string scene_path = default_scene_;
    bool measure_regrowth = false;
    if (const auto it = parameters.find("set"); it != parameters.end()) set = grow_set(it->second);
    if (const auto it = parameters.find("scene"); it != parameters.end()) {
      const std::string s = parameter_string(it->second, "scene");
      scene_path = s == "open" ? std::string() : resolve(s);
    }
    if (const auto it = parameters.find("measure_regrowth"); it != parameters.end()) {
      measure_regrowth = parameter_integer(it->second, "measure_regrowth") != 0;
    }
    const env::Scene empty;
    const env::Scene& full = scene_path.empty() ? empty : scene(scene_path);
    const env::Scene open = open_version(full);

    RunResult result;
    Clock::time_point t0 = Clock::now();
    env::GrowthResult grown =
        env::grow_tree(params, set == GrowSet::kBesideObstacles ? full : open);
    result.metrics["grow_seconds"] = seconds_since(t0);
    context.check();
    if (set != GrowSet::kAdapted) {
      result.tree = std::move(grown.tree);
    } else {
      env::AnalysisParams ap;
      ap.phototropism = params.phototropism;
      ap.gravitropism = params.gravitropism;
      ap.gravity_direction = params.gravity_direction;
      ap.gamma0 = params.gamma0;
      ap.min_cluster_radius_m = params.cluster_radius_m;
      ap.light_directions = params.light_directions;
      ap.light_significance = params.light_significance;
      ap.light_model = adapt_light_model(parameters);
      const env::TreeAnalysis analysis = env::analyze_tree(grown.tree, ap, open.sky.brightest);
      context.check();
      t0 = Clock::now();
      env::AdaptationResult adapted = env::adapt_tree(grown.tree, analysis, full);
      result.metrics["adapt_seconds"] = seconds_since(t0);
      result.metrics["pruned_nodes"] = static_cast<double>(adapted.pruned_nodes);
      result.metrics["tip_displacement"] = adapted.mean_tip_displacement_m;
      result.tree = env::remove_pruned(adapted.tree);
      if (measure_regrowth) {
        context.check();
        t0 = Clock::now();
        const env::GrowthResult regrown = env::grow_tree(params, full);
        result.metrics["regrow_seconds"] = seconds_since(t0);
      }
    }
    // The growth model's leaf clusters (leaf nodes), in set T as the adaptation moved them, so
    // that the metric means the same for sets O, G and T.
    result.metrics["light_interception"] =
        light_interception(set == GrowSet::kOpen ? open : full, leaf_cluster_spheres(*result.tree));
    // The crown's light under the growth's sky (its real sky when the parameters give one).
    env::Scene lit = set == GrowSet::kOpen ? open : full;
    lit.sky.directions = params.light_directions;
    if (params.site_sky) {
      env::apply_sky_distribution(lit.sky, std::make_shared<const env::SkyDistribution>(
                                               env::sky_distribution(*params.site_sky)));
    }
    add_canopy_light_metrics(lit, leaf_cluster_spheres(*result.tree), result.metrics);
    for (auto& [name, value] : tree_metrics(*result.tree)) result.metrics[name] = value;
    return result;
  }

 private:
  const env::Scene& scene(const std::string& path) const { return scenes_.get(path); }
  std::string resolve(const std::string& path) const { return scenes_.resolve(path); }

  // The parameter file's table with the run's growth parameters put over it, read by the growth
  // parameter parser so that names, ranges and messages are those of `fspm grow`.
  env::GrowthParams growth_params(const ParameterSet& parameters, std::uint64_t seed) const {
    toml::table table = parse_toml_text(base_text_, base_name_);
    for (const auto& [name, value] : parameters) {
      if (is_run_parameter(name)) continue;
      if (name == "seed") throw ValueError("seed: the growth seed is the run's seed");
      std::visit([&](const auto& v) { table.insert_or_assign(name, v); }, value);
    }
    // The run's seed, kept within TOML's signed integers.
    table.insert_or_assign("seed", static_cast<std::int64_t>(seed >> 1));
    std::ostringstream text;
    text << table;
    return env::parse_growth_params(text.str(), base_name_);
  }

  // Parameters of the run, not of the growth model.
  static bool is_run_parameter(const std::string& name) {
    return name == "set" || name == "scene" || name == "measure_regrowth" ||
           name == "adapt_light_model";
  }

  // The cluster light of set T's adaptation; the growth model's own light model does not choose
  // it. Without `adapt_light_model` it is the adaptation's default, the one `fspm adapt` uses.
  static env::ClusterLightModel adapt_light_model(const ParameterSet& parameters) {
    const auto it = parameters.find("adapt_light_model");
    if (it == parameters.end()) return env::AnalysisParams{}.light_model;
    return env::cluster_light_model_from_name(parameter_string(it->second, "adapt_light_model"));
  }

  std::string base_text_;
  std::string base_name_;
  std::string default_scene_;
  SceneCache scenes_;
};

}  // namespace

std::unique_ptr<Model> make_grow_model(const std::string& params_file,
                                       const std::string& scene_file, const std::string& base_dir) {
  return std::make_unique<GrowModel>(params_file, scene_file, base_dir);
}

}  // namespace fspm::experiments
