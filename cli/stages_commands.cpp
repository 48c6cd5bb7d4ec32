// fspm stages: developmental stages of a static tree (Pirk chapter 5).
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.hpp"
#include "cli/enum_option.hpp"
#include "cli/output.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "scans/mesh_file.hpp"
#include "stages/developmental_model.hpp"
#include "stages/mesh_skeleton.hpp"
#include "stages/profile_diagram.hpp"

namespace fspm::cli {
namespace {

struct StagesOptions {
  std::string tree;
  std::string output;
  std::string format;
  double at = -1.0;
  int steps = 0;
  int season_years = 0;
  // The options bound straight into the model's and the mesh skeleton's parameters, whose
  // defaults are the options'.
  stages::StagesParams params;
  stages::MeshSkeletonParams skeleton_params;
  double profile_m = 0.0;
  std::vector<std::string> age_branch;   // NODE:DT (Pirk 5.4.1)
  std::vector<std::string> copy_branch;  // FROM:TO
  bool json = false;
  // Mesh input (Pirk 5.2.1).
  std::string skeleton;
  bool uniform_laplacian = false;
};

// The given tree: a tree file, or the skeleton of a branch mesh (.obj, .ply, .gltf, .glb) by
// contraction, whose figures go to `info`.
TreeGraph read_given_tree(const StagesOptions& o, nlohmann::json& info) {
  if (!scans::is_mesh_file(o.tree)) return read_tree_file(o.tree);
  const auto t0 = std::chrono::steady_clock::now();
  const scans::GroupedMesh m = scans::read_mesh_file(o.tree);
  const double read_seconds = seconds_since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  stages::MeshSkeletonParams params = o.skeleton_params;
  if (o.uniform_laplacian) params.contraction.weights = stages::LaplacianWeights::kUniform;
  stages::MeshSkeleton s;
  try {
    s = stages::mesh_skeleton(stages::weld_branch_mesh(m.vertices, m.faces), params);
  } catch (const ValueError& e) {
    if (!e.file().empty()) throw;
    throw ValueError(e.message(), o.tree);  // "the mesh has no triangle": which mesh
  }
  info = {{"vertices", m.vertices.size()},          {"faces", m.faces.size()},
          {"contraction_iterations", s.iterations}, {"area_ratio", s.area_ratio},
          {"join_distance_m", s.join_distance_m},   {"skeleton_internodes", s.tree.size()},
          {"read_seconds", read_seconds},           {"skeleton_seconds", seconds_since(t1)}};
  spdlog::info(
      "{}: {} vertices contracted in {} iteration(s) (area ratio {:.2g}), joined within "
      "{:.3g} m into a skeleton of {} internodes",
      o.tree, m.vertices.size(), s.iterations, s.area_ratio, s.join_distance_m, s.tree.size());
  if (!o.skeleton.empty()) write_tree_file(s.tree, o.skeleton);
  return std::move(s.tree);
}

// The stage times: one (--at) or N evenly spaced in (0, 1] (--steps), remapped by the seasons.
std::vector<double> stage_times(const StagesOptions& o) {
  if ((o.at >= 0.0) == (o.steps > 0)) {
    throw ValueError("give either --at T (one stage) or --steps N (a sequence)");
  }
  std::vector<double> times;
  if (o.at >= 0.0) {
    times.push_back(o.at);
  } else {
    for (int k = 1; k <= o.steps; ++k) times.push_back(static_cast<double>(k) / o.steps);
  }
  if (o.season_years > 0) {
    for (double& t : times) t = stages::seasonal_time(t, o.season_years);
  }
  return times;
}

// --steps: OUT is a folder of stage_NNN files (created if missing).
std::string stage_path(const StagesOptions& o, std::size_t k) {
  if (o.steps <= 0) return o.output;
  char name[32];
  std::snprintf(name, sizeof name, "stage_%03zu.%s", k + 1,
                o.format.empty() ? "treeb" : o.format.c_str());
  return (std::filesystem::path(o.output) / name).string();
}

// Pirk 5.3.4: the given tree's profile diagrams by both clipping methods, layers from the ground.
nlohmann::json profile_json(const TreeGraph& tree, double layer_m) {
  const stages::DevelopmentalModel plain(tree);
  nlohmann::json out = {{"layer_m", layer_m}};
  for (const stages::Clipping c : {stages::Clipping::kStratified, stages::Clipping::kMainAxis}) {
    const stages::ProfileDiagram p = stages::profile_diagram(tree, plain.chain(), layer_m, c);
    out[std::string(stages::clipping_name(c))] = {{"leaves", p.leaves},
                                                  {"wood_m3", p.wood_m3},
                                                  {"leaves_above", p.leaves_above},
                                                  {"tissue_above", p.tissue_above}};
  }
  return out;
}

// "A:B" split at its one colon into two non-empty parts; throws ValueError naming `option`.
std::pair<std::string, std::string> split_pair(const std::string& text, const char* option,
                                               const char* form) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0 || colon + 1 == text.size() ||
      text.find(':', colon + 1) != std::string::npos) {
    throw ValueError(std::string(option) + ": expected " + form + ", got '" + text + "'");
  }
  return {text.substr(0, colon), text.substr(colon + 1)};
}

NodeId parse_node(const std::string& text, const char* option) {
  std::size_t used = 0;
  unsigned long id = 0;
  try {
    id = std::stoul(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || text.front() == '-' || id >= kNoNode) {
    throw ValueError(std::string(option) + ": '" + text + "' is not a node id");
  }
  return static_cast<NodeId>(id);
}

// Pirk 5.4.1: --age-branch NODE:DT (DT in units of t, or NODE:Ky for K years with
// --season-years N, DT = K / N) and --copy-branch FROM:TO.
stages::BranchEdits branch_edits(const StagesOptions& o) {
  stages::BranchEdits edits;
  for (const std::string& a : o.age_branch) {
    auto [node, delta] = split_pair(a, "--age-branch", "NODE:DT (e.g. 812:0.1 or 812:-2y)");
    const bool years = delta.back() == 'y';
    if (years) delta.pop_back();
    if (years && o.season_years <= 0) {
      throw ValueError("--age-branch " + a + ": a change in years needs --season-years N");
    }
    std::size_t used = 0;
    double dt = 0.0;
    try {
      dt = std::stod(delta, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != delta.size() || !std::isfinite(dt)) {
      throw ValueError("--age-branch " + a + ": '" + delta + "' is not a number");
    }
    edits.age.push_back({parse_node(node, "--age-branch"), years ? dt / o.season_years : dt});
  }
  for (const std::string& c : o.copy_branch) {
    const auto [from, to] = split_pair(c, "--copy-branch", "FROM:TO (e.g. 812:40)");
    edits.copy.push_back({parse_node(from, "--copy-branch"), parse_node(to, "--copy-branch")});
  }
  return edits;
}

void run_stages(const StagesOptions& o) {
  refuse_overwriting_input(o.output, {o.tree});
  if (!o.skeleton.empty()) refuse_overwriting_input(o.skeleton, {o.tree});
  refuse_same_output(o.output, "-o", o.skeleton, "--skeleton");
  const std::vector<double> times = stage_times(o);
  nlohmann::json mesh_info;
  const TreeGraph tree = read_given_tree(o, mesh_info);
  auto t0 = std::chrono::steady_clock::now();
  stages::StagesParams params = o.params;
  params.added.enabled = params.added.enabled || params.added.overlap;  // --added-overlap: --added
  params.edits = branch_edits(o);
  const stages::DevelopmentalModel model(tree, params);
  const double analysis_seconds = seconds_since(t0);
  if (o.steps > 0) std::filesystem::create_directories(o.output);
  TreeGraph stage;
  double stage_seconds = 0.0;
  for (std::size_t k = 0; k < times.size(); ++k) {
    t0 = std::chrono::steady_clock::now();
    model.stage(times[k], stage);
    stage_seconds += seconds_since(t0);
    write_tree_file(stage, stage_path(o, k), o.steps > 0 ? std::string_view{} : o.format);
  }
  std::size_t branches = 0;
  for (NodeId i = 0; i < tree.size(); ++i) branches += tree.kind(i) == OrganKind::kInternode;
  if (params.shed.enabled && model.shed_branch_count() == 0) {
    spdlog::warn(
        "--shed-branches: no radius of {} holds more pipes than its branches need, so no shed "
        "branch was read back; a tree grown by fspm keeps them with --set keep_shed_pipes=true",
        o.tree);
  }
  spdlog::info("{}: {} internodes in {} chains; {} added branch(es); {} stage(s) -> {}", o.tree,
               branches, model.chain_count(), model.added_branch_count(), times.size(), o.output);
  if (o.json) {
    nlohmann::json profile;
    if (o.profile_m > 0.0) profile = profile_json(tree, o.profile_m);
    print_json({{"branches", branches},
                {"profile", profile},
                {"mesh", mesh_info},
                {"chains", model.chain_count()},
                {"added_branches", model.added_branch_count()},
                {"overlap_branches", model.overlap_branch_count()},
                {"shed_branches", model.shed_branch_count()},
                {"crown_ratio", model.crown().crown_ratio()},
                {"stages", times.size()},
                {"times", times},
                {"last_stage_nodes", stage.size()},
                {"analysis_seconds", analysis_seconds},
                {"seconds_per_stage", stage_seconds / static_cast<double>(times.size())},
                {"output", o.output}});
  }
}

}  // namespace

void add_stages_commands(CLI::App& app) {
  auto o = std::make_shared<StagesOptions>();
  CLI::App* s = app.add_subcommand(
      "stages",
      "Developmental stages of a static tree (Pirk ch. 5): any stage from young to the given tree");
  s->add_option("TREE", o->tree,
                "The grown tree (.tree, .treeb, .nwk, .mtg), or its branch mesh (.obj, .ply, "
                ".gltf, .glb), whose skeleton is found by mesh contraction (Pirk 5.2.1)")
      ->required();
  s->add_option("-o,--output", o->output,
                "Tree file for --at; folder of stage_NNN files for --steps")
      ->required();
  s->add_option("--at", o->at, "One stage at time T in [0, 1] (1: the given tree)")
      ->check(number_in(0.0, 1.0));
  s->add_option("--steps", o->steps, "N stages at 1/N, 2/N, ..., 1")->check(number_in(1, 100000));
  s->add_option("--season-years", o->season_years,
                "Seasonal growth over N years (Pirk eq. 5.11, c = 1.2)")
      ->check(number_in(1, 10000));
  s->add_flag("--added", o->params.added.enabled,
              "Add the branches a young tree had below the crown and shed them as the crown "
              "ratio falls (Pirk 5.3.5-5.3.6, eq. 5.10)");
  s->add_flag("--added-overlap", o->params.added.overlap,
              "--added, and also fill the overlap region above the crown base where stratified "
              "clipping finds more tissue than main-axis cutting (Pirk 5.3.5)");
  s->add_option("--added-gamma", o->params.added.gamma,
                "gamma of eq. 5.10 for --added (1: the last stage is the given tree; < 1 keeps "
                "some added branches, > 1 sheds them earlier)")
      ->check(number_in(1e-6, 100.0))
      ->capture_default_str();
  add_enum_option(s, "--growth-profiles", o->params.profiles, stages::kProfileChoiceNames,
                  "Growth-rate profiles of the chains (Pirk 5.3.1)");
  s->add_flag("--shed-branches", o->params.shed.enabled,
              "Stand a shed branch wherever a radius holds more pipes than its children need "
              "(pipe model, Shinozaki et al. 1964), grown as its closest lateral and shed when "
              "complete");
  s->add_option("--age-branch", o->age_branch,
                "NODE:DT: make the branch holding internode NODE older by DT (units of t; "
                "negative: younger), or by K years as NODE:Ky with --season-years; it shows at "
                "each stage what it would show DT later (Pirk 5.4.1). Repeatable")
      ->allow_extra_args(false);
  s->add_option("--copy-branch", o->copy_branch,
                "FROM:TO: copy the branch holding internode FROM to the end of internode TO, "
                "moved rigidly and growing from the time the tree reaches TO, at the age FROM "
                "had when it started (Pirk 5.4.1). Repeatable")
      ->allow_extra_args(false);
  s->add_option("--profile", o->profile_m,
                "With --json: the given tree's profile diagrams (Pirk 5.3.4) in layers of this "
                "many metres, by stratified clipping and main-axis cutting")
      ->check(number_in(1e-3, 1000.0));
  s->add_option("--skeleton", o->skeleton,
                "With a mesh: also write the skeleton found (the given tree) to this tree file");
  s->add_option("--join-distance", o->skeleton_params.join_distance_m,
                "With a mesh: t_dist of Pirk eq. 5.1 in metres, contracted vertices closer than "
                "this are joined (default: the median distance a vertex moved, about the median "
                "branch radius)")
      ->check(number_in(0.0, 1e6));
  s->add_flag("--uniform-laplacian", o->uniform_laplacian,
              "With a mesh: contract with uniform instead of cotangent Laplacian weights");
  s->add_option("--format", o->format, "tree, treeb, nwk, mtg (default: from the extension)");
  s->add_flag("--json", o->json,
              "One JSON object on stdout: branches, chains, stages, analysis_seconds, "
              "seconds_per_stage; for a mesh, \"mesh\": vertices, contraction_iterations, "
              "join_distance_m, skeleton_seconds");
  s->callback([o] { run_stages(*o); });
}

}  // namespace fspm::cli
