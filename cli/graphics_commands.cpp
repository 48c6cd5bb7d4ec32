// fspm mesh | render: tree meshes for ParaView, Blender and glTF viewers; offscreen figures.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/image.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"

namespace fspm::cli {
namespace {

struct MeshCommand {
  std::string tree;
  std::string format;
  std::string out;
  bool leaves = false;
  std::vector<double> ages;
  double edge_length_m = 0.01;
  int max_sides = 16;
  std::string junctions = "separate";
  bool reynolds_width = false;
  bool json = false;
};

graphics::JunctionMode junction_mode(const std::string& name) {
  if (name == "separate") return graphics::JunctionMode::kSeparate;
  if (name == "continuous") return graphics::JunctionMode::kContinuous;
  throw ValueError("unknown junction mode '" + name + "' (expected separate or continuous)");
}

struct RenderCommand {
  std::string tree;
  std::string format;
  std::string out;
  std::string color_by;
  std::string view = "iso";
  std::string size = "1024x768";
  bool leaves = false;
  bool no_ground = false;
  double edge_length_m = 0.01;
  bool json = false;
};

struct ViewCommand {
  std::vector<std::string> trees;
  std::string format;
  std::vector<double> ages;
  std::string color_by;
  std::string screenshot;
  std::string size = "1280x800";
  int frames = 1;
  bool leaves = false;
  bool no_shadows = false;
  bool json = false;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void run_mesh(const MeshCommand& c) {
  const auto t0 = std::chrono::steady_clock::now();
  const graphics::MeshFormat format = graphics::mesh_format_for(c.out);
  const TreeGraph tree = read_tree_file(c.tree, c.format);
  graphics::MeshOptions options;
  options.leaves = c.leaves;
  options.edge_length_m = c.edge_length_m;
  options.max_sides = c.max_sides;
  options.junctions = junction_mode(c.junctions);
  options.reynolds_width = c.reynolds_width;
  nlohmann::json j = {{"file", c.tree}, {"output", c.out}};
  std::size_t vertices = 0, triangles = 0;
  if (format == graphics::MeshFormat::kPvd) {
    const std::vector<double> ages = c.ages.empty() ? graphics::default_ages(tree) : c.ages;
    const auto frames = graphics::write_pvd(tree, options, ages, c.out);
    nlohmann::json list = nlohmann::json::array();
    for (const auto& f : frames) {
      vertices += f.vertices;
      triangles += f.triangles;
      list.push_back({{"age", f.age},
                      {"file", f.vtp_path},
                      {"vertices", f.vertices},
                      {"triangles", f.triangles}});
    }
    j["frames"] = list;
  } else {
    if (!c.ages.empty()) {
      throw ValueError("--ages makes a growth sequence: use an output ending in .pvd", c.out);
    }
    const graphics::TriangleMesh mesh = graphics::mesh_tree(tree, options);
    graphics::write_mesh(mesh, c.out);
    vertices = mesh.vertex_count();
    triangles = mesh.triangle_count();
  }
  j["vertices"] = vertices;
  j["triangles"] = triangles;
  j["seconds"] = seconds_since(t0);
  if (c.json) {
    print_json(j);
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << c.out << " (" << vertices << " vertices, " << triangles
              << " triangles)\n";
  }
}

// VTK's OpenGL context needs an X display. Without one, run this same command again under a
// virtual X server (xvfb-run) rather than failing; FSPM_UNDER_XVFB stops a second attempt.
void rerun_under_xvfb_if_needed() {
  if (graphics::display_available() || std::getenv("FSPM_UNDER_XVFB") != nullptr) return;
  const char* xvfb_run = "/usr/bin/xvfb-run";
  if (!std::filesystem::exists(xvfb_run)) return;
  std::ifstream cmdline("/proc/self/cmdline", std::ios::binary);
  const std::string all{std::istreambuf_iterator<char>(cmdline), {}};
  std::vector<std::string> args;
  for (std::size_t at = 0; at < all.size();) {
    const std::size_t end = all.find('\0', at);
    args.push_back(all.substr(at, end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  if (ec || args.empty()) return;
  spdlog::info("no X display: rendering under xvfb-run");
  std::vector<std::string> words = {xvfb_run, "-a", "-s", "-screen 0 1280x1024x24", self};
  words.insert(words.end(), args.begin() + 1, args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  ::setenv("FSPM_UNDER_XVFB", "1", 1);
  std::cout.flush();
  std::cerr.flush();
  ::execv(xvfb_run, argv.data());
  ::unsetenv("FSPM_UNDER_XVFB");  // exec failed: fall through to the clear error of render_mesh
}

void run_render(const RenderCommand& c) {
  const auto t0 = std::chrono::steady_clock::now();
  graphics::RenderOptions options;
  options.view = graphics::view_from_name(c.view);
  graphics::parse_size(c.size, options.width, options.height);
  options.color_by = c.color_by;
  options.ground = !c.no_ground;
  if (!graphics::render_available()) {
    throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
  }
  graphics::check_image_path(c.out);
  const TreeGraph tree = read_tree_file(c.tree, c.format);
  graphics::MeshOptions mesh_options;
  mesh_options.leaves = c.leaves;
  mesh_options.edge_length_m = c.edge_length_m;
  const graphics::TriangleMesh mesh = graphics::mesh_tree(tree, mesh_options);
  if (!c.color_by.empty()) (void)mesh.attribute(c.color_by);  // unknown attribute: ValueError
  rerun_under_xvfb_if_needed();
  const graphics::Image image = graphics::render_mesh(mesh, options);
  graphics::write_image(image, c.out);
  if (c.json) {
    print_json({{"file", c.tree},
                {"output", c.out},
                {"width", image.width},
                {"height", image.height},
                {"triangles", mesh.triangle_count()},
                {"seconds", seconds_since(t0)}});
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << c.out << " (" << image.width << "x" << image.height << ")\n";
  }
}

// Every tree meshed at every age, placed side by side along x with a gap of a tenth of the
// widest tree.
std::vector<graphics::TriangleMesh> view_steps(const ViewCommand& c, std::vector<double>& ages,
                                               const graphics::MeshOptions& resolution) {
  std::vector<TreeGraph> trees;
  for (const auto& path : c.trees) trees.push_back(read_tree_file(path, c.format));
  graphics::MeshOptions options = resolution;
  options.leaves = c.leaves;
  if (ages.empty()) ages.push_back(std::numeric_limits<double>::infinity());
  std::sort(ages.begin(), ages.end());
  std::vector<float> offsets;
  float x = 0.0f;
  for (const auto& t : trees) {
    const graphics::TriangleMesh full = graphics::mesh_tree(t, options);
    const float width = full.empty() ? 0.0f : full.bbox_max().x() - full.bbox_min().x();
    offsets.push_back(full.empty() ? x : x - full.bbox_min().x());
    x += width * 1.1f + 0.1f;
  }
  std::vector<graphics::TriangleMesh> steps;
  for (double age : ages) {
    graphics::TriangleMesh scene;
    for (std::size_t i = 0; i < trees.size(); ++i) {
      options.max_birth_time = age;
      graphics::TriangleMesh m = graphics::mesh_tree(trees[i], options);
      for (auto& p : m.positions) p.x() += offsets[i];
      scene.append(m);
    }
    steps.push_back(std::move(scene));
  }
  return steps;
}

void run_view(const ViewCommand& c) {
  const auto t0 = std::chrono::steady_clock::now();
  if (!graphics::viewer_available()) {
    throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
  }
  graphics::ViewerOptions options;
  graphics::parse_size(c.size, options.width, options.height);
  options.color_by = c.color_by;
  options.screenshot = c.screenshot;
  options.frames = c.frames;
  options.shadows = !c.no_shadows;
  if (!c.screenshot.empty()) graphics::check_image_path(c.screenshot);
  std::vector<double> ages = c.ages;
  const std::vector<graphics::TriangleMesh> steps = view_steps(c, ages, {});
  // Far level of detail: rings four times coarser, at most six sides.
  graphics::MeshOptions coarse;
  coarse.edge_length_m *= 4.0;
  coarse.max_sides = 6;
  coarse.min_sides = 3;
  std::vector<double> same_ages = ages;
  const std::vector<graphics::TriangleMesh> far = view_steps(c, same_ages, coarse);
  if (!c.color_by.empty()) {
    for (const auto& m : steps) (void)m.attribute(c.color_by);
  }
  if (!c.screenshot.empty()) rerun_under_xvfb_if_needed();
  const graphics::ViewerStats stats = graphics::run_viewer(steps, ages, options, far);
  if (c.json) {
    print_json({{"frames", stats.frames},
                {"mean_frame_ms", stats.mean_frame_ms},
                {"triangles", stats.triangles},
                {"screenshot", c.screenshot},
                {"seconds", seconds_since(t0)}});
  }
}

}  // namespace

void add_graphics_commands(CLI::App& app) {
  const std::string formats = "tree, treeb, nwk (default: from the extension)";

  auto mesh = std::make_shared<MeshCommand>();
  CLI::App* m = app.add_subcommand(
      "mesh", "Mesh a tree: generalized cylinders along its chains, leaves as quads");
  m->add_option("TREE", mesh->tree, "Tree file")->required();
  m->add_option("-o,--output", mesh->out, "Output: .obj (+.mtl), .ply, .vtp, .pvd or .glb")
      ->required();
  m->add_option("--format", mesh->format, "Input format: " + formats);
  m->add_flag("--leaves", mesh->leaves, "Mesh leaf nodes as quads");
  m->add_option("--ages", mesh->ages,
                "Ages of a .pvd growth sequence (default: the birth times, at most 20)")
      ->delimiter(',');
  m->add_option("--edge-length", mesh->edge_length_m,
                "Target ring edge length in m (ring resolution from radius)")
      ->check(CLI::PositiveNumber);
  m->add_option("--max-sides", mesh->max_sides, "Most sides of a ring")->check(CLI::Range(3, 256));
  m->add_option("--junctions", mesh->junctions,
                "separate (a closed tube per chain) or continuous (Reynolds: one surface through "
                "branch points, bone weights per vertex)")
      ->capture_default_str();
  m->add_flag("--reynolds-width", mesh->reynolds_width,
              "Continuous mode: radius along each axis from Reynolds' expression 1");
  m->add_flag("--json", mesh->json, "Machine-readable JSON on stdout");
  m->callback([mesh] { run_mesh(*mesh); });

  auto render = std::make_shared<RenderCommand>();
  CLI::App* r = app.add_subcommand("render", "Offscreen figure of a tree with VTK");
  r->add_option("TREE", render->tree, "Tree file")->required();
  r->add_option("-o,--output", render->out, "Image: .png, .tif or .exr")->required();
  r->add_option("--format", render->format, "Input format: " + formats);
  r->add_option("--color-by", render->color_by,
                "Colour by a vertex attribute (age, birth_time, order, physiological_age or a "
                "tree attribute) with a scalar bar");
  r->add_option("--view", render->view, "front, side, top or iso")->capture_default_str();
  r->add_option("--size", render->size, "WIDTHxHEIGHT in pixels")->capture_default_str();
  r->add_flag("--leaves", render->leaves, "Show leaves");
  r->add_flag("--no-ground", render->no_ground, "Leave out the ground plane");
  r->add_option("--edge-length", render->edge_length_m, "Target ring edge length in m")
      ->check(CLI::PositiveNumber);
  r->add_flag("--json", render->json, "Machine-readable JSON on stdout");
  r->callback([render] { run_render(*render); });

  auto view = std::make_shared<ViewCommand>();
  CLI::App* v = app.add_subcommand(
      "view",
      "Real-time viewer: drag to orbit, right-drag to pan, wheel to zoom, [ ] growth steps, "
      "S shadows, R reset, Esc quit");
  v->add_option("FILE", view->trees, "Tree files (placed side by side)")->required();
  v->add_option("--format", view->format, "Input format: " + formats);
  v->add_option("--ages", view->ages, "Growth steps shown with [ and ]")->delimiter(',');
  v->add_option("--color-by", view->color_by, "Colour by a vertex attribute");
  v->add_flag("--leaves", view->leaves, "Show leaves");
  v->add_flag("--no-shadows", view->no_shadows, "Start without shadows");
  v->add_option("--size", view->size, "Window WIDTHxHEIGHT")->capture_default_str();
  v->add_option("--screenshot", view->screenshot,
                "Render hidden, write this image after --frames frames and exit");
  v->add_option("--frames", view->frames, "Frames before the screenshot")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  v->add_flag("--json", view->json, "Machine-readable JSON on stdout (frame time)");
  v->callback([view] { run_view(*view); });
}

}  // namespace fspm::cli
