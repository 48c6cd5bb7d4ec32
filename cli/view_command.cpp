// fspm view: the real-time viewer of trees, plants, scenes, L-systems, growth sequences and
// crowns.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/enum_option.hpp"
#include "cli/full_command_list.hpp"
#include "cli/graphics_options.hpp"
#include "cli/output.hpp"
#include "cli/wind_skin.hpp"
#include "cli/xvfb.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/image.hpp"
#include "graphics/scene_file.hpp"
#include "graphics/viewer.hpp"
#include "graphics/viewer_wind.hpp"
#include "graphics/vtk_readback.hpp"
#include "io/input_kind.hpp"
#include "io/input_mesh.hpp"
#include "io/lod_scene.hpp"
#include "io/lsystem_mesh.hpp"
#include "io/placed_mesh.hpp"
#include "io/stepped_input.hpp"
#include "stages/developmental_model.hpp"

namespace fspm::cli {
namespace {

using io::input_kind;
using io::InputKind;
using io::is_compressed;

struct ViewCommand {
  std::vector<std::string> trees;
  std::string format;
  std::vector<double> ages;
  // The options bound straight into the viewer and mesh options, whose defaults are the options'.
  graphics::ViewerOptions viewer;
  graphics::MeshOptions mesh;
  std::string size = graphics::size_text(viewer.width, viewer.height);
  int frames = 0;  // 0: not given
  bool no_shadows = false;
  bool no_panel = false;
  std::vector<double> look_at;  // empty or X, Y, Z
  bool lod = false;
  double lod_distance_m = 0.0;
  bool no_impostors = false;
  bool no_ground = false;
  bool full_detail = false;  // no coarse meshes at any distance
  int stages = 0;            // developmental stages per tree file (0: none)
  bool wind = false;
  WindArguments wind_args;
  bool ray_cast = false;
  LsystemDrawArguments lsystem;
  GraphLodArguments graph_lod;
  bool json = false;
};

// The mesh options' defaults with the leaves of the command line (--leaves, --foliage, --seed):
// the wind's and the ray-cast crowns' meshes take no other mesh option.
graphics::MeshOptions leaves_options(const ViewCommand& c) {
  graphics::MeshOptions options;
  options.leaves = c.mesh.leaves;
  options.foliage = c.mesh.foliage;
  options.foliage_seed = c.mesh.foliage_seed;
  return options;
}

// fspm view --lod: one scene (or tree, or plant) with its plants chosen per instance each frame.
void run_lod_view(const ViewCommand& c, const graphics::ViewerOptions& options,
                  std::chrono::steady_clock::time_point t0) {
  if (c.trees.size() != 1 || !c.ages.empty()) {
    throw ValueError("--lod shows one scene, tree or plant file, without --ages");
  }
  graphics::MeshOptions mesh_options = leaves_options(c);
  mesh_options.axis_subdivisions = c.mesh.axis_subdivisions;
  const graphics::LodScene scene =
      io::load_lod_scene(c.trees[0], c.format, mesh_options, graphics::LodOptions{}, true, "");
  graphics::LodOptions lod = io::lod_options(scene, c.lod_distance_m);
  // Impostors where expression 2 would cull (the renders keep the coarsest mesh there).
  lod.impostor_distance_m = c.no_impostors ? 0.0 : lod.max_distance_m;
  graphics::ViewerOptions with_terrain = options;
  // A terrain is the ground: no plane under it.
  if (input_kind(c.trees[0]) == InputKind::kScene &&
      read_scene_description(c.trees[0]).terrain.has_value()) {
    with_terrain.ground = false;
  }
  if (!options.screenshot.empty()) rerun_under_xvfb_if_needed();
  const graphics::ViewerStats stats = graphics::run_lod_viewer(scene, lod, with_terrain);
  if (c.json) {
    print_json({{"frames", stats.frames},
                {"mean_frame_ms", stats.mean_frame_ms},
                {"first_frame_ms", stats.first_frame_ms},
                {"shadow_maps_drawn", stats.shadow_maps_drawn},
                {"triangles", stats.triangles},
                {"impostors", stats.impostors},
                {"plants", scene.placements.size()},
                {"lod_distance_m", lod.max_distance_m},
                {"screenshot", options.screenshot},
                {"seconds", seconds_since(t0)}});
  }
}

graphics::ViewerOptions viewer_options(const ViewCommand& c) {
  graphics::ViewerOptions options = c.viewer;
  graphics::parse_size(c.size, options.width, options.height);
  // --frames: before the screenshot, or, without one, before the window closes by itself.
  options.frames = c.frames > 0 ? c.frames : 1;
  if (options.screenshot.empty()) options.close_after_frames = c.frames;
  options.shadows = !c.no_shadows;
  options.panel = !c.no_panel;
  options.ground = !c.no_ground;
  if (!c.look_at.empty()) options.look_at = {c.look_at[0], c.look_at[1], c.look_at[2]};
  return options;
}

// A growth sequence written by fspm mesh -o X.pvd (or any ParaView collection of .vtp triangle
// meshes): one step per data set, the age keys stepping through its time steps.
void load_pvd_steps(const ViewCommand& c, std::vector<graphics::InstancedMesh>& steps,
                    std::vector<double>& ages) {
  if (c.trees.size() != 1) throw ValueError("fspm view opens one .pvd sequence at a time");
  if (!c.ages.empty()) throw ValueError("--ages does not apply to a .pvd (its time steps do)");
  if (!graphics::vtk_available()) {
    throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): cannot read .vtp steps");
  }
  for (const auto& step : graphics::read_pvd_file(c.trees[0])) {
    steps.push_back(graphics::InstancedMesh::single(graphics::read_vtp_mesh(step.path)));
    ages.push_back(step.time);
  }
}

// Trees, plants, scenes and L-systems read (and checked) before any window opens; the ages of
// the compressed plants when --ages gives none.
// --stages N: the times 1/N, 2/N, ..., 1 of the stages, each tree file as its own model.
void check_stages_view(const ViewCommand& c, std::vector<double>& ages) {
  if (c.stages <= 0) return;
  if (!c.ages.empty()) throw ValueError("--stages and --ages exclude each other");
  for (const auto& path : c.trees) {
    if (input_kind(path) != InputKind::kTree) {
      throw ValueError("--stages takes tree files (.tree, .treeb, .nwk, .mtg), not '" + path + "'");
    }
  }
  ages.clear();
  for (int k = 1; k <= c.stages; ++k) ages.push_back(static_cast<double>(k) / c.stages);
}

std::vector<io::SteppedInput> read_view_sources(const ViewCommand& c, int size_px,
                                                std::vector<double>& ages) {
  std::vector<io::SteppedInput> sources;
  for (const auto& path : c.trees) {
    io::SteppedInput s;
    s.path = path;
    s.kind = input_kind(path);
    s.lod = c.graph_lod.lod();
    if (is_compressed(s.kind)) {
      s.graph = io::load_compressed(path, s.kind);
      if (ages.empty()) ages = io::plant_ages(s.graph);
    } else if (s.kind == InputKind::kTree) {
      s.tree = read_tree_file(path, c.format);
      if (s.lod.active()) s.tree = reduce_tree(s.tree, s.lod);
      if (c.stages > 0) s.model = std::make_shared<const stages::DevelopmentalModel>(s.tree);
    } else if (s.kind == InputKind::kLsystem) {
      s.drawing = draw_lsystem_file(path, c.lsystem, size_px);
    } else if (s.kind == InputKind::kMesh) {
      s.mesh = io::read_placed_mesh(path);
    } else {
      (void)graphics::read_scene_file(path);  // bad scene: error before any window
    }
    sources.push_back(std::move(s));
  }
  return sources;
}

// The meshes of every age step, and a far level of detail: rings four times coarser, at most
// six sides. Returns the far meshes' ring edge length.
double mesh_view_steps(const ViewCommand& c, const std::vector<io::SteppedInput>& sources,
                       std::vector<double>& ages, std::vector<graphics::InstancedMesh>& steps,
                       std::vector<graphics::InstancedMesh>& far) {
  if (ages.empty()) ages.push_back(std::numeric_limits<double>::infinity());
  std::sort(ages.begin(), ages.end());
  graphics::MeshOptions mesh_options = c.mesh;
  mesh_options.min_sides = std::min(mesh_options.min_sides, mesh_options.max_sides);
  steps = io::steps_side_by_side(sources, ages, mesh_options);
  graphics::MeshOptions coarse = mesh_options;
  coarse.axis_subdivisions = 1;  // far away: straight internodes
  coarse.edge_length_m *= 4.0;
  coarse.max_sides = std::min(6, mesh_options.max_sides);
  coarse.min_sides = 3;
  double held_bytes = 0.0;
  for (const auto& step : steps) held_bytes += io::stored_bytes(step);
  far = io::steps_side_by_side(sources, ages, coarse, held_bytes);
  return coarse.edge_length_m;
}

void print_view_json(const ViewCommand& c, const std::vector<graphics::InstancedMesh>& steps,
                     const graphics::ViewerStats& stats, std::chrono::steady_clock::time_point t0) {
  std::size_t meshes = 0, instances = 0;
  for (const auto& step : steps) {
    meshes += step.meshes.size();
    instances += step.instances.size();
  }
  print_json({{"frames", stats.frames},
              {"tessellation", stats.tessellation},
              {"cpu_tessellation_level", stats.cpu_tessellation_level},
              {"mean_frame_ms", stats.mean_frame_ms},
              {"first_frame_ms", stats.first_frame_ms},
              {"shadow_maps_drawn", stats.shadow_maps_drawn},
              {"triangles", stats.triangles},
              {"steps", steps.size()},
              {"meshes", meshes},
              {"instances", instances},
              {"screenshot", c.viewer.screenshot},
              {"seconds", seconds_since(t0)}});
}

// fspm view TREE --wind: the tree swaying as fspm mesh --skin --animate and fspm render
// --wind-time pose it (the same bones, weights, wind model and phases from --seed), posed every
// frame, its strength on the panel.
void run_wind_view(const ViewCommand& c, graphics::ViewerOptions options,
                   std::chrono::steady_clock::time_point t0) {
  if (c.trees.size() != 1 || input_kind(c.trees[0]) != InputKind::kTree) {
    throw ValueError("--wind sways one tree file (.tree, .treeb, .nwk, .mtg)");
  }
  if (!c.ages.empty() || c.stages > 0 || c.lod) {
    throw ValueError("--wind takes no --ages, --stages or --lod");
  }
  const TreeGraph tree = read_tree_file(c.trees[0], c.format);
  const graphics::MeshOptions mesh_options = leaves_options(c);
  auto wind = std::make_shared<graphics::ViewerWind>();
  wind->mesh = skinnable_mesh(tree, mesh_options);
  wind->skin = graphics::skin_mesh(tree, wind->mesh);
  wind->wind = wind_options(c.wind_args, c.wind_args.options.duration_s, mesh_options.foliage_seed);
  if (!options.color_by.empty()) (void)wind->mesh.attribute(options.color_by);
  const std::vector<graphics::InstancedMesh> steps{graphics::InstancedMesh::single(wind->mesh)};
  options.wind = std::move(wind);
  if (!options.screenshot.empty()) rerun_under_xvfb_if_needed();
  const std::vector<double> ages{std::numeric_limits<double>::infinity()};
  const graphics::ViewerStats stats = graphics::run_instanced_viewer(steps, ages, options);
  if (c.json) print_view_json(c, steps, stats, t0);
}

// fspm view CROWN|SCENE --ray-cast: crowns from fspm crown drawn by relief-mapped ray casting of
// their cubemaps (Argudo 5.1) in place of their triangles; trunks and everything else stay meshes.
void run_ray_cast_view(const ViewCommand& c, graphics::ViewerOptions options,
                       std::chrono::steady_clock::time_point t0) {
  if (!c.ages.empty() || c.stages > 0 || c.lod || c.wind) {
    throw ValueError("--ray-cast takes no --ages, --stages, --lod or --wind");
  }
  RayCastInput in = load_ray_cast_input(c.trees, leaves_options(c));
  options.relief_crowns = std::move(in.crowns);
  const std::vector<graphics::InstancedMesh> steps{std::move(in.meshes)};
  if (!options.screenshot.empty()) rerun_under_xvfb_if_needed();
  const std::vector<double> ages{std::numeric_limits<double>::infinity()};
  const graphics::ViewerStats stats = graphics::run_instanced_viewer(steps, ages, options);
  if (c.json) print_view_json(c, steps, stats, t0);
}

void run_view(ViewCommand c) {
  const auto t0 = std::chrono::steady_clock::now();
  for (std::string& path : c.trees) path = io::resolve_crown_folder(path);
  if (!graphics::viewer_available()) {
    throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
  }
  if (!c.viewer.screenshot.empty()) check_inputs_readable_twice(c.trees);
  graphics::ViewerOptions options = viewer_options(c);
  if (c.stages > 0) options.step_label = "time";
  if (!options.screenshot.empty()) graphics::check_image_path(options.screenshot);
  check_lsystem_draw_arguments(c.lsystem, c.trees);
  check_graph_lod(c.graph_lod, c.trees, c.lod);
  if (c.wind) {
    run_wind_view(c, options, t0);
    return;
  }
  if (c.ray_cast) {
    run_ray_cast_view(c, options, t0);
    return;
  }
  if (c.stages > 0 && c.lod) throw ValueError("--stages and --lod exclude each other");
  if (c.lod) {
    run_lod_view(c, options, t0);
    return;
  }
  std::vector<double> ages = c.ages;
  check_stages_view(c, ages);
  std::vector<graphics::InstancedMesh> steps, far;
  const bool pvd = std::any_of(c.trees.begin(), c.trees.end(), [](const std::string& p) {
    return input_kind(p) == InputKind::kPvd;
  });
  if (pvd) {
    load_pvd_steps(c, steps, ages);
  } else {
    const auto sources = read_view_sources(c, std::max(options.width, options.height), ages);
    options.coarse_edge_m = mesh_view_steps(c, sources, ages, steps, far);
    if (c.full_detail) {
      far.clear();
      options.coarse_edge_m = 0.0;
    }
  }
  if (!options.color_by.empty()) {
    for (const auto& step : steps) {
      for (const auto& m : step.meshes) (void)m.attribute(options.color_by);
    }
  }
  if (!options.screenshot.empty()) rerun_under_xvfb_if_needed();
  const graphics::ViewerStats stats = graphics::run_instanced_viewer(steps, ages, options, far);
  if (c.json) print_view_json(c, steps, stats, t0);
}

}  // namespace

void add_view_command(CLI::App& app) {
  auto view = std::make_shared<ViewCommand>();
  CLI::App* v = app.add_subcommand(kViewCommand.name, kViewCommand.description);
  v->add_option(
       "FILE", view->trees,
       "Tree files (.tree, .treeb, .nwk, .mtg), compressed plants (.ctree, plant .toml), "
       "scenes (.json) or L-systems (.l), placed side by side; or one .pvd growth sequence")
      ->required();
  add_input_format_option(v, view->format);
  v->add_option("--ages", view->ages,
                "Growth steps shown with [ and ]: plant ages of compressed graphs (default: each "
                "cycle), latest birth times of trees")
      ->delimiter(',');
  v->add_option("--color-by", view->viewer.color_by, "Colour by a vertex attribute");
  add_leaves_options(v, view->mesh, "Show leaves and leaf clusters");
  v->add_flag("--no-shadows", view->no_shadows, "Start without shadows");
  v->add_flag("--no-panel", view->no_panel,
              "Hide the controls panel (growth step, shadows, level-of-detail distance, colour "
              "attribute, frame time and triangles)");
  v->add_option("--pitch-deg", view->viewer.pitch_deg,
                "Starting camera elevation above the horizontal, degrees (a few: a low view)")
      ->check(CLI::Range(-89.0, 89.0))
      ->capture_default_str();
  v->add_option("--yaw-deg", view->viewer.yaw_deg,
                "Starting camera azimuth, degrees counter-clockwise from +x (the eye's direction "
                "from the point looked at)")
      ->check(CLI::Range(-360.0, 360.0))
      ->capture_default_str();
  v->add_option("--look-at", view->look_at,
                "Starting point looked at, X,Y,Z in m (default: the centre of the scene)")
      ->delimiter(',')
      ->expected(3);
  v->add_option("--distance", view->viewer.camera_distance_m,
                "Starting camera distance from the point looked at, m (default: the whole scene "
                "in view)")
      ->check(positive_number(1e9));
  v->add_option("--shadow-cascades", view->viewer.shadow_cascades,
                "Cascaded shadow maps: N maps over slices of the view up to three camera "
                "distances away, nearest first, before the one map of the whole scene (sharp "
                "shadows near the camera over a landscape; one redrawn a frame while the camera "
                "moves; also on the panel)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  v->add_option("--size", view->size, "Window WIDTHxHEIGHT")->capture_default_str();
  v->add_option("--screenshot", view->viewer.screenshot,
                "Render hidden, write this image after --frames frames and exit");
  v->add_option("--frames", view->frames,
                "Frames before the screenshot (default 1); without --screenshot, the window "
                "closes after this many frames")
      ->check(CLI::Range(1, 100000));
  v->add_option("--stages", view->stages,
                "Developmental stages of each tree file (Pirk 5, as fspm stages): N stages from "
                "t = 1/N to the given tree at t = 1, stepped with [ and ] and the panel's slider")
      ->check(CLI::Range(1, 200));
  CLI::Option* wind = v->add_flag(
      "--wind", view->wind,
      "Sway the tree in the wind (one tree file; Reynolds' bones and weights, the wind of fspm "
      "mesh --skin --animate; its strength on the panel)");
  add_wind_options(v, view->wind_args, false);
  for (const char* name :
       {"--wind-amplitude", "--wind-frequency", "--wind-direction", "--wind-period"}) {
    v->get_option(name)->needs(wind);
  }
  add_ray_cast_flag(v, view->ray_cast);
  add_lod_options(v, view->lod, view->lod_distance_m);
  CLI::Option* lod = v->get_option("--lod");
  v->add_flag("--no-impostors", view->no_impostors,
              "With --lod: draw far plants as their coarsest mesh instead of impostors (one quad "
              "showing the plant's image from the nearest of 24 directions) beyond the "
              "--lod-distance")
      ->needs(lod);
  v->add_flag("--no-ground", view->no_ground, "Leave out the ground plane");
  v->add_flag("--full-detail", view->full_detail,
              "Never draw the coarse meshes (by default they take over where their ring edges "
              "span two pixels, or from 1.5 times the starting distance)")
      ->excludes(lod);
  add_axis_subdivisions_option(v, view->mesh);
  v->add_option("--max-sides", view->mesh.max_sides,
                "Most sides of a ring (4: Reynolds' coarse branch mesh, for --tessellate)")
      ->check(CLI::Range(3, 256))
      ->capture_default_str()
      ->excludes(lod);
  CLI::Option* tessellate =
      v->add_option("--tessellate", view->viewer.tessellation_max_level,
                    "Tessellate the opaque triangles up to level L (Reynolds' expression 2: finer "
                    "near the camera and for edges longer on the screen), new vertices on curved "
                    "PN triangles; tessellation shaders where the context has them, else on the "
                    "CPU")
          ->check(CLI::Range(1.0, 64.0))
          ->excludes(lod)
          ->excludes(v->get_option("--wind"));
  v->add_option("--tessellation-distance", view->viewer.tessellation_distance_m,
                "D_max of expression 2 in m (default 4 times the starting camera distance)")
      ->check(positive_number(1e9))
      ->needs(tessellate);
  v->add_flag("--tessellate-on-cpu", view->viewer.tessellation_on_cpu,
              "Tessellate on the CPU even where tessellation shaders exist (one level for the "
              "scene, from the starting camera distance)")
      ->needs(tessellate);
  add_lsystem_draw_options(v, view->lsystem);
  add_graph_lod_options(v, view->graph_lod);
  v->add_flag("--json", view->json, "Machine-readable JSON on stdout (frame time)");
  v->callback([view] { run_view(*view); });
}

}  // namespace fspm::cli
