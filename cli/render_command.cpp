// fspm render: offscreen figures of trees, plants, scenes, L-systems, scans and crowns.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/enum_option.hpp"
#include "cli/full_command_list.hpp"
#include "cli/graphics_options.hpp"
#include "cli/output.hpp"
#include "cli/wind_skin.hpp"
#include "cli/xvfb.hpp"
#include "environment/scene_file.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"
#include "io/input_kind.hpp"
#include "io/input_mesh.hpp"
#include "io/lod_scene.hpp"
#include "io/lsystem_mesh.hpp"
#include "io/scene_obstacles.hpp"

namespace fspm::cli {
namespace {

using io::input_kind;
using io::InputKind;
using io::is_compressed;

struct RenderCommand {
  std::string tree;
  std::string format;
  std::string out;
  // The options bound straight into the render and mesh options, whose defaults are the options'.
  graphics::RenderOptions render;
  graphics::MeshOptions mesh;
  std::string size = graphics::size_text(render.width, render.height);
  bool no_ground = false;
  std::string frame;
  std::string obstacles;
  double wind_time_s = -1.0;
  WindArguments wind;
  bool lod = false;
  double lod_distance_m = 0.0;
  LsystemDrawArguments lsystem;
  GraphLodArguments graph_lod;
  bool ray_cast = false;
  bool json = false;
};

// --wind-time: one tree posed at that time of its wind animation, framed as at rest.
graphics::InstancedMesh wind_frame(const RenderCommand& c, const graphics::MeshOptions& options,
                                   graphics::RenderOptions& render) {
  if (input_kind(c.tree) != InputKind::kTree) {
    throw ValueError("--wind-time needs one tree file (.tree, .treeb, .nwk, .mtg)", c.tree);
  }
  WindFrame f = posed_in_wind(read_tree_file(c.tree, c.format), options, c.wind, c.wind_time_s,
                              options.foliage_seed);
  render.frame = f.frame;
  return graphics::InstancedMesh::single(std::move(f.mesh));
}

// fspm render --lod: the plants chosen per instance for the render's camera.
void run_lod_render(const RenderCommand& c, const graphics::MeshOptions& mesh_options,
                    const graphics::RenderOptions& options,
                    std::chrono::steady_clock::time_point t0) {
  if (c.wind_time_s >= 0.0 || !c.render.color_by.empty() || !c.frame.empty()) {
    throw ValueError("--lod does not combine with --wind-time, --color-by or --frame");
  }
  const graphics::LodScene scene =
      io::load_lod_scene(c.tree, c.format, mesh_options, graphics::LodOptions{}, true, c.obstacles);
  const graphics::LodOptions lod = io::lod_options(scene, c.lod_distance_m);
  rerun_under_xvfb_if_needed();
  std::size_t triangles = 0;
  const graphics::Image image = graphics::render_lod_scene(scene, lod, options, &triangles);
  graphics::write_image(image, c.out);
  if (c.json) {
    print_json({{"file", c.tree},
                {"output", c.out},
                {"width", image.width},
                {"height", image.height},
                {"triangles", triangles},
                {"plants", scene.placements.size()},
                {"lod_distance_m", lod.max_distance_m},
                {"seconds", seconds_since(t0)}});
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << c.out << " (" << image.width << "x" << image.height << ")\n";
  }
}

void run_render(RenderCommand c) {
  c.tree = io::resolve_crown_folder(c.tree);
  refuse_overwriting_input(c.out, {c.tree, c.obstacles, c.frame});
  check_inputs_readable_twice({c.tree, c.obstacles, c.frame});
  const auto t0 = std::chrono::steady_clock::now();
  graphics::RenderOptions options = c.render;
  graphics::parse_size(c.size, options.width, options.height);
  options.ground = !c.no_ground;
  if (!graphics::render_available()) {
    throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
  }
  graphics::check_image_path(c.out);
  const graphics::MeshOptions& mesh_options = c.mesh;
  const bool lsystem = input_kind(c.tree) == InputKind::kLsystem;
  check_lsystem_draw_arguments(c.lsystem, {c.tree});
  check_graph_lod(c.graph_lod, {c.tree}, c.lod);
  if (c.graph_lod.lod().active() && c.wind_time_s >= 0.0) {
    throw ValueError("--wind-time poses the tree as it is: no --max-order or --merge-collinear");
  }
  if (c.lod) {
    if (c.ray_cast) throw ValueError("--ray-cast takes no --lod, --wind-time or --color-by");
    if (lsystem) throw ValueError("--lod does not apply to L-system files (.l)", c.tree);
    run_lod_render(c, mesh_options, options, t0);
    return;
  }
  nlohmann::json lsystem_summary;
  graphics::InstancedMesh mesh;
  if (c.ray_cast) {
    if (c.wind_time_s >= 0.0 || !options.color_by.empty()) {
      throw ValueError("--ray-cast takes no --lod, --wind-time or --color-by");
    }
    RayCastInput in = load_ray_cast_input({c.tree}, mesh_options);
    options.relief_crowns = std::move(in.crowns);
    mesh = std::move(in.meshes);
  } else if (c.wind_time_s >= 0.0) {
    mesh = wind_frame(c, mesh_options, options);
  } else if (lsystem) {
    const LsystemDrawing drawing =
        draw_lsystem_file(c.tree, c.lsystem, std::max(options.width, options.height));
    lsystem_summary = drawing.summary;
    mesh = io::mesh_lsystem(drawing, mesh_options);
  } else {
    mesh = io::load_render_input(c.tree, c.format, mesh_options, c.graph_lod.lod());
  }
  if (!c.frame.empty()) options.frame = io::frame_of(c.frame, mesh_options);
  if (mesh_options.leaves) report_missing_leaves(mesh, c.tree);
  if (!options.color_by.empty()) {
    for (const auto& m : mesh.meshes) (void)m.attribute(options.color_by);  // unknown: ValueError
  }
  // Obstacles take 0 for every attribute; the renderer draws them in stone all the same.
  if (!c.obstacles.empty()) {
    io::add_scene_obstacles(mesh, environment::read_scene_file(c.obstacles), c.obstacles, true);
  }
  const std::size_t obstacle_triangles = io::obstacle_triangle_count(mesh);
  rerun_under_xvfb_if_needed();
  const graphics::Image image = graphics::render_scene(mesh, options);
  graphics::write_image(image, c.out);
  if (c.json) {
    nlohmann::json j = {{"file", c.tree},
                        {"output", c.out},
                        {"width", image.width},
                        {"height", image.height},
                        {"triangles", mesh.triangle_count()},
                        {"obstacle_triangles", obstacle_triangles},
                        {"meshes", mesh.meshes.size()},
                        {"instances", mesh.instances.size()},
                        {"seconds", seconds_since(t0)}};
    if (lsystem) j["lsystem"] = lsystem_summary;
    print_json(j);
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << c.out << " (" << image.width << "x" << image.height << ")\n";
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  auto render = std::make_shared<RenderCommand>();
  CLI::App* r = app.add_subcommand(kRenderCommand.name, kRenderCommand.description);
  r->add_option(
       "TREE", render->tree,
       "Tree file (.tree, .treeb, .nwk, .mtg), compressed plant (.ctree, plant .toml), "
       "scene (.json), L-system (.l, with the .v beside it), point set (.ply, .xyz, "
       ".txt, .csv, .pcd, .las: small spheres) or cluster-based tree (.clusters: skeleton and "
       "translucent cluster hulls)")
      ->required();
  add_lsystem_draw_options(r, render->lsystem);
  r->add_option("-o,--output", render->out, "Image: .png, .tif or .exr")->required();
  add_input_format_option(r, render->format);
  r->add_option("--color-by", render->render.color_by,
                "Colour by a vertex attribute (age, birth_time, order, physiological_age or a "
                "tree attribute) with a scalar bar");
  add_enum_option(r, "--view", render->render.view, kViews, view_name, "Camera direction");
  r->add_option("--size", render->size, "WIDTHxHEIGHT in pixels")->capture_default_str();
  add_leaves_options(r, render->mesh, "Show leaves and leaf clusters");
  r->add_flag("--no-ground", render->no_ground, "Leave out the ground plane");
  add_axis_subdivisions_option(r, render->mesh);
  r->add_option("--edge-length", render->mesh.edge_length_m, "Target ring edge length in m")
      ->check(positive_number(1e6))
      ->capture_default_str();
  r->add_option("--ortho-height", render->render.ortho_height_m,
                "Parallel projection whose image height spans this many metres (a known scale)")
      ->check(positive_number(1e6));
  r->add_option("--frame", render->frame,
                "Aim the camera at this file's bounds instead (any TREE input): pictures of one "
                "tree's points, skeleton, clusters and reconstruction that line up");
  r->add_option("--obstacles", render->obstacles,
                "Scene file (.json, docs/formats.md) whose walls, boxes, spheres and meshes near "
                "the tree are drawn in stone (long walls cut to the tree's surroundings; a scene "
                "given as TREE draws its own)");
  r->add_option("--wind-time", render->wind_time_s,
                "Draw the tree posed at this time (s) of the wind animation of fspm mesh --skin "
                "--animate (same --seed and wind options); frames of a movie")
      ->check(number_in(0.0, 1e9));
  add_wind_options(r, render->wind, false);
  add_lod_options(r, render->lod, render->lod_distance_m);
  add_graph_lod_options(r, render->graph_lod);
  add_ray_cast_flag(r, render->ray_cast);
  r->add_flag("--json", render->json, "Machine-readable JSON on stdout");
  r->callback([render] { run_reporting_command([&] { run_render(*render); }); });
}

}  // namespace fspm::cli
