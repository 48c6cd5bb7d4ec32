// fspm mesh: tree meshes for ParaView, Blender and glTF viewers.
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/enum_option.hpp"
#include "cli/full_command_list.hpp"
#include "cli/graphics_options.hpp"
#include "cli/output.hpp"
#include "cli/wind_skin.hpp"
#include "environment/scene_file.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/mesh_writers.hpp"
#include "greenlab/expand.hpp"
#include "io/input_kind.hpp"
#include "io/input_mesh.hpp"
#include "io/lsystem_mesh.hpp"
#include "io/scene_obstacles.hpp"

namespace fspm::cli {
namespace {

using io::input_kind;
using io::InputKind;
using io::is_compressed;

struct MeshCommand {
  std::string tree;
  std::string format;
  std::string out;
  std::vector<double> ages;
  // The options bound straight into the mesh options, whose defaults are the options'.
  graphics::MeshOptions mesh;
  std::string obstacles;
  bool skin = false;
  double animate_s = 0.0;
  WindArguments wind;
  LsystemDrawArguments lsystem;
  GraphLodArguments graph_lod;
  bool json = false;
};

// --skin writes one tree's bark as a skinned .glb; --animate needs --skin.
void check_skin_request(const MeshCommand& c, graphics::MeshFormat format, InputKind kind) {
  if (format != graphics::MeshFormat::kGlb) {
    throw ValueError("--skin writes a glTF skin: use an output ending in .glb", c.out);
  }
  if (kind != InputKind::kTree) {
    throw ValueError("--skin needs one tree file (.tree, .treeb, .nwk, .mtg)", c.tree);
  }
  if (!c.ages.empty() || !c.obstacles.empty()) {
    throw ValueError("--skin does not combine with --ages or --obstacles");
  }
}

// Combinations of flags the mesh command refuses before reading anything.
void check_mesh_request(const MeshCommand& c, graphics::MeshFormat format, InputKind kind) {
  if (c.animate_s > 0.0 && !c.skin) throw ValueError("--animate needs --skin");
  check_lsystem_draw_arguments(c.lsystem, {c.tree});
  check_graph_lod(c.graph_lod, {c.tree}, false);
  if (c.skin && c.graph_lod.lod().active()) {
    throw ValueError("--skin writes the tree as it is: no --max-order or --merge-collinear");
  }
  if (kind == InputKind::kLsystem && (format == graphics::MeshFormat::kPvd || !c.ages.empty())) {
    throw ValueError("an L-system is meshed as derived: no .pvd growth sequence, no --ages",
                     c.tree);
  }
  if (c.skin) check_skin_request(c, format, kind);
}

// One tree's bark as a skinned .glb with its wind animation (Reynolds 3.3).
void write_skinned_mesh(const MeshCommand& c, const graphics::MeshOptions& options,
                        nlohmann::json& j) {
  const TreeGraph tree = read_tree_file(c.tree, c.format);
  const SkinnedOutput out =
      write_wind_glb(tree, options, c.wind, c.animate_s, options.foliage_seed, c.out);
  j["vertices"] = out.vertices;
  j["triangles"] = out.triangles;
  j["joints"] = out.joints;
  j["keyframes"] = out.keyframes;
}

// A growth sequence: one .vtp per age. A compressed plant's explicit tree is filtered by birth
// date (Jaeger 3.2.2).
void write_growth_sequence(const MeshCommand& c, InputKind kind,
                           const graphics::MeshOptions& options, nlohmann::json& j) {
  if (kind == InputKind::kScene || kind == InputKind::kPvd) {
    throw ValueError("a .pvd growth sequence is made from one tree or plant", c.tree);
  }
  if (!c.obstacles.empty()) {
    throw ValueError("--obstacles applies to .obj, .ply, .vtp and .glb outputs, not .pvd", c.out);
  }
  greenlab::ReconstructionOptions ro;
  ro.lod = c.graph_lod.lod();
  const TreeGraph tree = is_compressed(kind)
                             ? greenlab::reconstruct(io::load_compressed(c.tree, kind), ro)
                             : reduce_tree(read_tree_file(c.tree, c.format), ro.lod);
  const std::vector<double> ages = c.ages.empty() ? graphics::default_ages(tree) : c.ages;
  const auto frames = graphics::write_pvd(tree, options, ages, c.out);
  std::size_t vertices = 0, triangles = 0;
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
  j["vertices"] = vertices;
  j["triangles"] = triangles;
}

// One mesh (instanced where the format keeps instances) of a tree, plant, scene or L-system,
// with the obstacles of --obstacles.
void write_single_mesh(const MeshCommand& c, InputKind kind, const graphics::MeshOptions& options,
                       nlohmann::json& j) {
  if (!c.ages.empty()) {
    throw ValueError("--ages makes a growth sequence: use an output ending in .pvd", c.out);
  }
  graphics::InstancedMesh mesh;
  if (kind == InputKind::kLsystem) {
    const LsystemDrawing drawing = draw_lsystem_file(c.tree, c.lsystem, 0);
    j["lsystem"] = drawing.summary;
    mesh = io::mesh_lsystem(drawing, options);
  } else {
    mesh = io::load_instanced(c.tree, c.format, options, false, c.graph_lod.lod());
  }
  if (c.mesh.leaves) report_missing_leaves(mesh, c.tree);
  if (!c.obstacles.empty()) {
    io::add_scene_obstacles(mesh, environment::read_scene_file(c.obstacles), c.obstacles, false);
  }
  j["obstacle_triangles"] = io::obstacle_triangle_count(mesh);
  graphics::write_mesh(mesh, c.out);
  j["vertices"] = mesh.vertex_count();
  j["triangles"] = mesh.triangle_count();
  j.update(instancing_json(mesh));
}

void run_mesh(MeshCommand c) {
  c.tree = io::resolve_crown_folder(c.tree);
  refuse_overwriting_input(c.out, {c.tree, c.obstacles});
  const auto t0 = std::chrono::steady_clock::now();
  const graphics::MeshFormat format = graphics::mesh_format_for(c.out);
  const InputKind kind = input_kind(c.tree);
  check_mesh_request(c, format, kind);
  const graphics::MeshOptions& options = c.mesh;
  nlohmann::json j = {{"file", c.tree}, {"output", c.out}};
  // The mesh and its companions (an .obj's .mtl, a .pvd's steps) all, or none of them.
  OutputTransaction outputs;
  if (c.skin) {
    write_skinned_mesh(c, options, j);
  } else if (format == graphics::MeshFormat::kPvd) {
    write_growth_sequence(c, kind, options, j);
  } else {
    write_single_mesh(c, kind, options, j);
  }
  outputs.commit();
  j["seconds"] = seconds_since(t0);
  if (c.json) {
    print_json(j);
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << c.out << " (" << j["vertices"] << " vertices, " << j["triangles"]
              << " triangles)\n";
  }
}

}  // namespace

void add_mesh_command(CLI::App& app) {
  auto mesh = std::make_shared<MeshCommand>();
  CLI::App* m = app.add_subcommand(kMeshCommand.name, kMeshCommand.description);
  m->add_option(
       "TREE", mesh->tree,
       "Tree file (.tree, .treeb, .nwk, .mtg), compressed plant (.ctree or plant .toml, meshed "
       "per substructure), scene (.json) or L-system (.l, with the .v beside it)")
      ->required();
  m->add_option("-o,--output", mesh->out,
                "Output: .obj (+.mtl), .ply, .vtp, .pvd or .glb (.glb keeps the instancing)")
      ->required();
  add_input_format_option(m, mesh->format);
  add_leaves_options(m, mesh->mesh, "Mesh leaf nodes as quads, leaf clusters as foliage");
  m->add_option("--ages", mesh->ages,
                "Ages of a .pvd growth sequence (default: the birth times, at most 20)")
      ->delimiter(',');
  m->add_option("--edge-length", mesh->mesh.edge_length_m,
                "Target ring edge length in m (ring resolution from radius)")
      ->check(positive_number(1e6))
      ->capture_default_str();
  m->add_option("--max-sides", mesh->mesh.max_sides, "Most sides of a ring")
      ->check(CLI::Range(3, 256))
      ->capture_default_str();
  add_axis_subdivisions_option(m, mesh->mesh);
  add_enum_option(m, "--junctions", mesh->mesh.junctions, graphics::kJunctionModeNames,
                  "How tubes meet at branch points (continuous, after Reynolds, carries bone "
                  "weights per vertex)");
  m->add_flag("--reynolds-width", mesh->mesh.reynolds_width,
              "Continuous mode: radius along each axis from Reynolds' expression 1");
  m->add_option("--obstacles", mesh->obstacles,
                "Scene file (.json, docs/formats.md) whose walls, boxes, spheres and meshes are "
                "added, whole, as material obstacle (not with .pvd; a scene given as TREE adds "
                "its own)");
  m->add_flag("--skin", mesh->skin,
              "Write the tree as a glTF skin (.glb): a joint per internode, Reynolds' bone "
              "weights as JOINTS_0/WEIGHTS_0 (implies --junctions continuous)");
  m->add_option("--animate", mesh->animate_s,
                "With --skin: add a looping wind animation this many seconds long (rotation "
                "keyframes per joint; phases from --seed)")
      ->check(positive_number(1e5));
  add_wind_options(m, mesh->wind, true);
  add_lsystem_draw_options(m, mesh->lsystem);
  add_graph_lod_options(m, mesh->graph_lod);
  m->add_flag("--json", mesh->json, "Machine-readable JSON on stdout");
  m->callback([mesh] { run_reporting_command([&] { run_mesh(*mesh); }); });
}

}  // namespace fspm::cli
