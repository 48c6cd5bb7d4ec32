// fspm adapt: plastic trees (Pirk 4.3-4.4). Each tree is analysed as grown in the open, then bent
// and pruned for the scene; the output carries per-node "displacement", "pruned" and
// "leaf_density". Several --scene options re-adapt the same analysed trees to each scene in turn
// (a scene change does not re-analyse): -o is then a directory with one sub-directory per scene.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

#include "cli/commands.hpp"
#include "cli/cpu_time.hpp"
#include "cli/enum_option.hpp"
#include "cli/output.hpp"
#include "environment/leaf_light.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/scene_file.hpp"
#include "environment/site_sky.hpp"
#include "environment/sky_distribution.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::cli {
namespace {

struct AdaptOptions {
  std::vector<std::string> trees;
  std::vector<std::string> scenes;
  std::string out;
  std::string format;
  // The options bound straight into the analysis parameters, whose defaults are the options'.
  environment::AnalysisParams analysis;
  std::vector<double> grown_brightest;
  std::string sky_file;
  bool keep_pruned = false;
  bool remove_pruned = true;  // the default; the flag only confirms it
  bool together = false;
  bool absolute_pruning = false;  // the inverse of analysis.relative_pruning
  bool json = false;
};

std::string scene_label(const std::string& path, std::size_t index,
                        const std::vector<std::string>& all) {
  std::string stem = std::filesystem::path(path).stem().string();
  if (stem.empty()) stem = "scene";
  // Two scenes with the same file name (in different folders) get their position appended.
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k != index && std::filesystem::path(all[k]).stem().string() == stem) {
      return stem + "_" + std::to_string(index + 1);
    }
  }
  return stem;
}

// Output paths for the trees: OUT itself for one tree, else OUT/<tree file name>.
std::vector<std::string> output_paths(const AdaptOptions& o, const std::filesystem::path& out,
                                      bool directory) {
  std::vector<std::string> outputs;
  if (directory) {
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) throw IoError("cannot create output directory: " + ec.message(), out.string());
    for (const std::string& in : o.trees) {
      std::filesystem::path name = std::filesystem::path(in).filename();
      if (!o.format.empty()) name.replace_extension(o.format == "newick" ? "nwk" : o.format);
      outputs.push_back((out / name).string());
    }
  } else {
    outputs.push_back(out.string());
  }
  for (const std::string& path : outputs) tree_format_for(path, o.format);  // fail early
  return outputs;
}

environment::AnalysisParams analysis_params(const AdaptOptions& o) {
  environment::AnalysisParams params = o.analysis;
  params.relative_pruning = !o.absolute_pruning;
  return params;
}

// The sky the trees grew under: --grown-brightest, else the first scene's.
Eigen::Vector3d grown_brightest(const AdaptOptions& o, const environment::Scene& first_scene) {
  if (o.grown_brightest.empty()) return first_scene.sky.brightest;
  Eigen::Vector3d b(o.grown_brightest[0], o.grown_brightest[1], o.grown_brightest[2]);
  if (b.z() <= 0.0) {
    throw ValueError("--grown-brightest: expected a direction above the horizon (z > 0)");
  }
  return b.normalized();
}

// The trees adapted to one scene, each alone or all together, with the seconds each took (wall
// clock, and CPU time of the thread).
std::vector<environment::AdaptationResult> adapt_to_scene(
    const AdaptOptions& o, const std::vector<TreeGraph>& trees,
    const std::vector<environment::TreeAnalysis>& analyses, const environment::Scene& scene,
    std::vector<double>& seconds, std::vector<double>& cpu_seconds) {
  std::vector<environment::AdaptationResult> adapted;
  seconds.clear();
  cpu_seconds.clear();
  if (o.together) {
    // Tree-tree interaction: lock-step adaptation in one light field (Pirk 4.4.3).
    std::vector<const TreeGraph*> tp;
    std::vector<const environment::TreeAnalysis*> ap;
    for (std::size_t k = 0; k < trees.size(); ++k) {
      tp.push_back(&trees[k]);
      ap.push_back(&analyses[k]);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds();
    adapted = environment::adapt_trees(tp, ap, scene);
    const double total = seconds_since(t0);
    seconds.assign(trees.size(), total / static_cast<double>(trees.size()));
    cpu_seconds.assign(trees.size(),
                       (thread_cpu_seconds() - c0) / static_cast<double>(trees.size()));
    return adapted;
  }
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = thread_cpu_seconds();
    adapted.push_back(environment::adapt_tree(trees[k], analyses[k], scene));
    seconds.push_back(seconds_since(t0));
    cpu_seconds.push_back(thread_cpu_seconds() - c0);
  }
  return adapted;
}

// Under a real sky (--sky): the adapted tree's leaf clusters get their PAR (record_leaf_par)
// through the adapted crown and the scene's obstacles, over the analysis' sky directions; returns
// their mean flux (nan without a real sky or clusters).
double record_adapted_par(TreeGraph& tree, const environment::Scene& scene,
                          const environment::AnalysisParams& params) {
  if (!scene.sky.distribution) return std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint32_t> sphere_of;
  const std::vector<environment::Sphere> clusters = environment::leaf_spheres(tree, sphere_of);
  if (clusters.empty()) return std::numeric_limits<double>::quiet_NaN();
  environment::Scene par_scene = scene;
  par_scene.sky.directions = params.light_directions;
  environment::record_leaf_par(tree, par_scene, clusters, sphere_of);
  double sum = 0.0;
  const auto par = tree.attribute(environment::kParAttribute);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (sphere_of[i] != environment::kNoSphere) sum += par[i];
  }
  return sum / static_cast<double>(clusters.size());
}

nlohmann::json json_vector(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json adapted_json(const environment::AdaptationResult& r, const std::string& input,
                            const std::string& output, std::size_t nodes, double seconds,
                            double cpu_seconds, double analysis_seconds) {
  return {{"input", input},
          {"output", output},
          {"nodes", nodes},
          {"pruned_nodes", r.pruned_nodes},
          {"mean_tip_displacement", r.mean_tip_displacement_m},
          {"mean_tip_shift", json_vector(r.mean_tip_shift)},
          {"pruned_centroid", json_vector(r.pruned_centroid)},
          {"internode_centroid", json_vector(r.internode_centroid)},
          {"seconds", seconds},
          {"cpu_seconds", cpu_seconds},
          {"analysis_seconds", analysis_seconds}};
}

void run_adapt(const AdaptOptions& o) {
  std::vector<environment::Scene> scenes;
  for (const std::string& path : o.scenes) scenes.push_back(environment::read_scene_file(path));
  const environment::AnalysisParams params = analysis_params(o);
  const Eigen::Vector3d brightest = grown_brightest(o, scenes.front());
  if (!o.sky_file.empty()) {
    // A real sky: every scene's sky becomes its light per direction (the sun's positions and the
    // diffuse sky, sky_distribution.hpp) with its mean light direction as the brightest point;
    // the trees grew under the scene's own sky (or --grown-brightest): a global light change.
    const auto real = std::make_shared<const environment::SkyDistribution>(
        environment::sky_distribution(environment::read_site_sky_file(o.sky_file)));
    for (environment::Scene& scene : scenes) {
      scene.sky.brightest = real->mean_direction();
      scene.sky.distribution = real;
    }
  }
  const bool many = o.trees.size() > 1;
  const bool several_scenes = scenes.size() > 1;
  std::vector<std::vector<std::string>> outputs;  // per scene, per tree
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    const std::filesystem::path out =
        several_scenes ? std::filesystem::path(o.out) / scene_label(o.scenes[s], s, o.scenes)
                       : std::filesystem::path(o.out);
    // With several scenes and one tree the file keeps the tree's name inside the scene folder.
    outputs.push_back(output_paths(o, out, many || several_scenes));
  }

  std::vector<TreeGraph> trees;
  for (const std::string& in : o.trees) trees.push_back(read_tree_file(in));
  std::vector<environment::TreeAnalysis> analyses;
  std::vector<double> analysis_seconds;
  for (const TreeGraph& tree : trees) {
    const auto t0 = std::chrono::steady_clock::now();
    // The open-sky analysis uses the sky the tree grew under (default: the first scene's), so a
    // moved brightest point is a global light change (Pirk 4.4.3). It is made once: every scene
    // re-adapts from it.
    analyses.push_back(environment::analyze_tree(tree, params, brightest));
    analysis_seconds.push_back(seconds_since(t0));
  }

  nlohmann::json results = nlohmann::json::array();
  for (std::size_t s = 0; s < scenes.size(); ++s) {
    std::vector<double> seconds, cpu_seconds;
    const std::vector<environment::AdaptationResult> adapted =
        adapt_to_scene(o, trees, analyses, scenes[s], seconds, cpu_seconds);
    for (std::size_t k = 0; k < trees.size(); ++k) {
      const environment::AdaptationResult& r = adapted[k];
      const std::string& output = outputs[s][k];
      // The adapted tree as it stands: pruned branches gone unless asked to keep them flagged.
      TreeGraph written = o.keep_pruned ? r.tree : environment::remove_pruned(r.tree);
      const double mean_par = record_adapted_par(written, scenes[s], params);
      write_tree_file(written, output, o.format);
      nlohmann::json item = adapted_json(r, o.trees[k], output, trees[k].size(), seconds[k],
                                         cpu_seconds[k], analysis_seconds[k]);
      if (std::isfinite(mean_par)) item["mean_leaf_par_umol_m2_s"] = mean_par;
      if (several_scenes) {
        item["scene"] = o.scenes[s];
        item["light_evaluations"] = r.light_evaluations;
      }
      results.push_back(std::move(item));
      spdlog::info(
          "{}{}: {} nodes, {} pruned, mean tip displacement {:.3f} m, adapted in {:.4f} s "
          "(analysis {:.4f} s) -> {}",
          o.trees[k], several_scenes ? " in " + o.scenes[s] : std::string(), trees[k].size(),
          r.pruned_nodes, r.mean_tip_displacement_m, seconds[k], analysis_seconds[k], output);
    }
  }
  if (o.json) print_json(many || several_scenes ? results : results.front());
}

}  // namespace

// --light-model: the models of adaptation, as add_enum_option shows them; a model of growth only
// (space_colonization) is refused by the registry's message, which names the use.
void add_cluster_light_model_option(CLI::App* app, environment::ClusterLightModel& value) {
  const auto& table = environment::kClusterLightModelNames;
  std::string choices;
  for (const NamedValue<environment::ClusterLightModel>& e : table.entries()) {
    choices += (choices.empty() ? "" : ", ") + std::string(e.name);
  }
  app->add_option("--light-model", value, "Cluster light: " + table.help())
      ->transform(CLI::Validator(
          [](std::string& input) -> std::string {
            try {
              const auto model = environment::cluster_light_model_from_name(input);
              input = std::to_string(static_cast<std::underlying_type_t<decltype(model)>>(model));
              return {};
            } catch (const ValueError& e) {
              return e.message();
            }
          },
          "one of: " + choices))
      ->default_str(std::string(table.name(value)));
}

void add_adapt_commands(CLI::App& app) {
  auto opt = std::make_shared<AdaptOptions>();
  CLI::App* a = app.add_subcommand(
      "adapt", "Plastic trees (Pirk 4.3-4.4): bend and prune trees grown in the open for a scene");
  a->add_option("TREE", opt->trees,
                "Input tree files (.tree, .treeb, .nwk, .mtg), grown without obstacles")
      ->required();
  a->add_option("--scene", opt->scenes,
                "Scene file (JSON, see docs/formats.md); repeat it to re-adapt the same "
                "analysed trees to several scenes (-o is then a directory, one folder per scene)")
      ->required()
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  a->add_option("-o,--output", opt->out,
                "Output tree file, or a directory when several trees or scenes are given")
      ->required();
  a->add_option("--format", opt->format, "Output format (default: from the extension)");
  a->add_option("--skeleton-radius", opt->analysis.skeleton_radius_m,
                "Skeleton thickness threshold in m (default: 2.5 x thinnest internode)")
      ->check(positive_number(1000));
  a->add_option("--pruning-strength", opt->analysis.pruning_strength, "c_psi of Pirk eq. 4.12")
      ->capture_default_str();
  a->add_option("--phototropism", opt->analysis.phototropism, "Phototropism weight (eq. 4.6)")
      ->capture_default_str();
  a->add_option("--gravitropism", opt->analysis.gravitropism, "Gravitropism weight (eq. 4.6)")
      ->capture_default_str();
  a->add_option("--grown-brightest", opt->grown_brightest,
                "Brightest sky direction x y z the trees grew under (default: the scene's)")
      ->expected(3)
      ->check(number_in(-1e6, 1e6));
  a->add_option("--sky", opt->sky_file,
                "TOML file with sky = { site = { latitude, longitude, elevation }, date, "
                "hours | days }: the scenes' sky becomes that real sky (its sun positions and "
                "diffuse light per direction); the adapted trees' leaf clusters get their PAR");
  a->add_flag("--temporal-pruning", opt->analysis.temporal_pruning,
              "Pruning thresholds over all earlier growth stages (eq. 4.5), not the final one");
  a->add_flag("--absolute-pruning", opt->absolute_pruning,
              "Pirk's eq. 4.12 thresholds as analysed, not scaled with the crown's resources");
  add_cluster_light_model_option(a, opt->analysis.light_model);
  a->add_option(
       "--canopy-model", opt->analysis.canopy_model,
       "Leaf light model of --light-model canopy: " + environment::leaf_light_model_names())
      ->capture_default_str();
  a->add_flag("--together", opt->together,
              "Trees shade each other, adapted in lock-step (world coordinates, Pirk 4.4.3)");
  a->add_flag("--keep-pruned", opt->keep_pruned,
              "Keep pruned nodes in the output, flagged by the attribute \"pruned\" (default: "
              "drop them)");
  // Removal became the default; the old flag stays accepted so scripts keep working.
  a->add_flag("--remove-pruned", opt->remove_pruned,
              "Drop pruned nodes (the default; kept for compatibility)")
      ->excludes("--keep-pruned");
  a->add_flag("--json", opt->json, "Machine-readable JSON on stdout");
  a->callback([opt] { run_reporting_command([&] { run_adapt(*opt); }); });
}

}  // namespace fspm::cli
