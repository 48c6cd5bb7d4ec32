// fspm mesh | render: tree meshes for ParaView, Blender and glTF viewers; offscreen figures.
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli/commands.hpp"
#ifdef FSPM_HAVE_CROWN
#include "cli/crown_cubemaps_file.hpp"
#endif
#include "cli/enum_option.hpp"
#include "cli/full_command_list.hpp"
#include "cli/graph_lod_option.hpp"
#include "cli/lsystem_mesh.hpp"
#include "cli/lsystem_source.hpp"
#include "cli/output.hpp"
#include "cli/placed_mesh.hpp"
#include "cli/scan_render_mesh.hpp"
#include "cli/scene_obstacles.hpp"
#include "cli/wind_skin.hpp"
#include "cli/xvfb.hpp"
#include "environment/scene_file.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/elapsed.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/scene_description.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/foliage.hpp"
#include "graphics/image.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/landscape.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/scene_file.hpp"
#include "graphics/tessellation_level.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "graphics/viewer_wind.hpp"
#include "graphics/vtk_readback.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/reconstruction.hpp"
#include "greenlab/simulation.hpp"
#include "lsystem/parser.hpp"
#include "stages/developmental_model.hpp"

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
  int axis_subdivisions = 1;
  std::string junctions = "separate";
  bool reynolds_width = false;
  std::string foliage = "leaves";
  std::uint64_t seed = 1;
  std::string obstacles;
  bool skin = false;
  double animate_s = 0.0;
  WindArguments wind;
  LsystemDrawArguments lsystem;
  GraphLodArguments graph_lod;
  bool json = false;
};

struct RenderCommand {
  std::string tree;
  std::string format;
  std::string out;
  std::string color_by;
  View view = View::kIso;
  std::string size = "1024x768";
  bool leaves = false;
  std::string foliage = "leaves";
  std::uint64_t seed = 1;
  bool no_ground = false;
  double edge_length_m = 0.01;
  int axis_subdivisions = 1;
  double ortho_height_m = 0.0;
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

struct ViewCommand {
  std::vector<std::string> trees;
  std::string format;
  std::vector<double> ages;
  std::string color_by;
  std::string screenshot;
  std::string size = "1280x800";
  int frames = 0;  // 0: not given
  bool leaves = false;
  std::string foliage = "leaves";
  std::uint64_t seed = 1;
  bool no_shadows = false;
  bool no_panel = false;
  double pitch_deg = 20.0;
  double yaw_deg = -51.56620156177409;  // ViewerOptions::yaw_deg
  std::vector<double> look_at;          // empty or X, Y, Z
  double distance_m = 0.0;
  int shadow_cascades = 0;
  bool lod = false;
  double lod_distance_m = 0.0;
  bool no_impostors = false;
  bool no_ground = false;
  bool full_detail = false;  // no coarse meshes at any distance
  int max_sides = 16;
  int axis_subdivisions = 1;
  double tessellate = 0.0;  // Reynolds' tessellation up to this level (0: none)
  double tessellation_distance_m = 0.0;
  bool tessellate_on_cpu = false;
  int stages = 0;  // developmental stages per tree file (0: none)
  bool wind = false;
  WindArguments wind_args;
  bool ray_cast = false;
  LsystemDrawArguments lsystem;
  GraphLodArguments graph_lod;
  bool json = false;
};

// Leaves on or off, and how leaf clusters are drawn (the name becomes an enum right away).
void set_leaves(graphics::MeshOptions& options, bool leaves, const std::string& foliage,
                std::uint64_t seed) {
  options.leaves = leaves;
  options.foliage.mode = graphics::foliage_mode_from_name(foliage);
  options.foliage_seed = seed;
}

// --leaves that finds no leaf, polygon or leaf cluster says so instead of drawing nothing quietly.
void report_missing_leaves(const graphics::InstancedMesh& mesh, const std::string& file) {
  for (const auto& m : mesh.meshes) {
    if (m.triangle_count(graphics::Material::kLeaf) + m.triangle_count(graphics::Material::kCrown) >
        0) {
      return;
    }
  }
  spdlog::warn("{}: --leaves found no leaves to draw (no leaf nodes with a length or a radius)",
               file);
}

// What a graphics command was given: a tree file, a compressed graph (.ctree) or a GreenLab plant
// description (.toml, simulated on the fly), a scene of many plants (.json), a ParaView growth
// sequence (.pvd, viewer only) or an L-system (.l, drawn by the turtle; not inside a scene).
enum class InputKind { kTree, kCompressed, kPlant, kScene, kPvd, kLsystem, kMesh };

InputKind input_kind(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == ".ctree") return InputKind::kCompressed;
  if (ext == ".toml") return InputKind::kPlant;
  if (ext == ".json") return InputKind::kScene;
  if (ext == ".pvd") return InputKind::kPvd;
  if (ext == ".l") return InputKind::kLsystem;
  if (is_placed_mesh_path(path)) return InputKind::kMesh;  // a crown from fspm crown
  return InputKind::kTree;
}

bool is_compressed(InputKind kind) {
  return kind == InputKind::kCompressed || kind == InputKind::kPlant;
}

CompressedTreeGraph load_compressed(const std::string& path, InputKind kind) {
  if (kind == InputKind::kCompressed) return read_ctree_file(path);
  return greenlab::simulate_compressed(greenlab::read_plant_params(path));
}

// Jaeger 3.1.2: one prototype per substructure, meshed once, placed by transforms.
graphics::InstancedMesh mesh_compressed(const CompressedTreeGraph& graph, double age,
                                        const graphics::MeshOptions& options,
                                        const LevelOfDetail& lod) {
  greenlab::ReconstructionOptions ro;
  ro.age = age;
  graphics::InstancedTree tree = greenlab::reconstruct_instanced(graph, ro);
  // Jaeger 3.1.1: the level of detail reduces the substructures before they are meshed.
  if (lod.active()) tree = reduce_instanced_tree(tree, lod);
  return graphics::mesh_instanced(tree, options);
}

// A tree meshed once, or a compressed plant meshed per substructure; `age` is the plant age of
// a compressed graph (< 0: as simulated) or, for a tree, the latest birth time kept.
graphics::InstancedMesh load_part(const std::string& path, InputKind kind,
                                  const std::string& format, double age,
                                  graphics::MeshOptions options, const LevelOfDetail& lod = {},
                                  const MtgTreeOptions& mtg = default_mtg_tree_options()) {
  if (is_compressed(kind)) return mesh_compressed(load_compressed(path, kind), age, options, lod);
  if (kind == InputKind::kScene) throw ValueError("a scene cannot include another scene", path);
  if (kind == InputKind::kMesh) return graphics::InstancedMesh::single(read_placed_mesh(path));
  if (kind == InputKind::kPvd) {
    throw ValueError("a .pvd is a growth sequence of meshes: open it with fspm view", path);
  }
  if (kind == InputKind::kLsystem) {
    throw ValueError(
        "an L-system (.l) is drawn by fspm render, mesh and view, not inside a scene or with "
        "--lod: write it as a plant first (fspm lsystem derive FILE --compressed -o PLANT.ctree)",
        path);
  }
  if (age >= 0.0) options.max_birth_time = age;
  TreeGraph tree = read_tree_file(path, format, mtg);
  if (lod.active()) tree = reduce_tree(tree, lod);
  return graphics::InstancedMesh::single(graphics::mesh_tree(tree, options));
}

// A crown's mesh from fspm crown without the crown's triangles (material leaf), which a ray-cast
// crown replaces; its trunk, if any, stays. The vertices stay too (they frame the view alike).
graphics::TriangleMesh without_crown(graphics::TriangleMesh mesh) {
  std::vector<graphics::TriangleMesh::Triangle> triangles;
  std::vector<graphics::Material> materials;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] == graphics::Material::kLeaf) continue;
    triangles.push_back(mesh.triangles[t]);
    materials.push_back(mesh.materials[t]);
  }
  mesh.triangles = std::move(triangles);
  mesh.materials = std::move(materials);
  return mesh;
}

// Each distinct plant file of a scene meshed once, placed as often as the scene says; with
// `crowns_ray_cast`, crowns from fspm crown without their crown triangles.
graphics::InstancedMesh place_plants(const graphics::SceneFile& scene,
                                     const graphics::MeshOptions& options, const LevelOfDetail& lod,
                                     bool crowns_ray_cast) {
  std::vector<graphics::InstancedMesh> parts;
  for (const auto& source : scene.sources) {
    const InputKind kind = input_kind(source.path);
    if (crowns_ray_cast && kind == InputKind::kMesh) {
      parts.push_back(
          graphics::InstancedMesh::single(without_crown(read_placed_mesh(source.path))));
      continue;
    }
    parts.push_back(load_part(source.path, kind, "", source.age, options, lod, source.mtg));
  }
  std::vector<graphics::PartPlacement> placements;
  for (const auto& inst : scene.instances) {
    placements.push_back({inst.source, inst.linear().cast<float>(), inst.position.cast<float>()});
  }
  return graphics::place_parts(parts, placements);
}

// A scene with its population's plants added to its plants; the terrain mesh, if any, in
// `terrain`.
SceneDescription read_landscape_scene(const std::string& path,
                                      std::optional<graphics::TriangleMesh>& terrain) {
  SceneDescription description = read_scene_description(path);
  graphics::Landscape landscape = graphics::scene_landscape(description);
  description.plants.insert(description.plants.end(), landscape.plants.begin(),
                            landscape.plants.end());
  terrain = std::move(landscape.terrain);
  return description;
}

// The terrain placed once, as it is (after the obstacles, which are cropped to the plants).
void add_terrain(graphics::InstancedMesh& mesh, std::optional<graphics::TriangleMesh>& terrain) {
  if (!terrain) return;
  graphics::MeshInstance inst;
  inst.mesh = static_cast<std::uint32_t>(mesh.meshes.size());
  mesh.meshes.push_back(std::move(*terrain));
  mesh.instances.push_back(inst);
}

// The plants of a scene file (its population's among them), its obstacles and its terrain:
// obstacles near the plants (`near_plants`, for pictures), or all of them whole. A scene without
// plants shows its obstacles whole.
graphics::InstancedMesh load_scene(const std::string& path, const graphics::MeshOptions& options,
                                   bool near_plants, const LevelOfDetail& lod = {},
                                   bool crowns_ray_cast = false) {
  std::optional<graphics::TriangleMesh> terrain;
  const SceneDescription description = read_landscape_scene(path, terrain);
  graphics::InstancedMesh mesh =
      place_plants(graphics::scene_plants(description.plants), options, lod, crowns_ray_cast);
  if (!description.obstacles.empty()) {
    add_scene_obstacles(mesh, environment::scene_from_description(description), path,
                        near_plants && !description.plants.empty());
  }
  add_terrain(mesh, terrain);
  return mesh;
}

graphics::InstancedMesh load_instanced(const std::string& path, const std::string& format,
                                       const graphics::MeshOptions& options, bool near_plants,
                                       const LevelOfDetail& lod = {}) {
  const InputKind kind = input_kind(path);
  if (kind == InputKind::kScene) return load_scene(path, options, near_plants, lod);
  return load_part(path, kind, format, -1.0, options, lod);
}

// --lod: the mesher options of the prebuilt resolutions, finest first: as given (with its
// B-spline rings, if any), rings four times coarser with at most six sides, sixteen times
// coarser with three sides, both with straight internodes.
std::vector<graphics::MeshOptions> lod_resolutions(const graphics::MeshOptions& finest) {
  graphics::MeshOptions middle = finest, coarse = finest;
  middle.axis_subdivisions = coarse.axis_subdivisions = 1;
  middle.edge_length_m *= 4.0;
  middle.max_sides = std::min(middle.max_sides, 6);
  middle.min_sides = 3;
  coarse.edge_length_m *= 16.0;
  coarse.max_sides = 3;
  coarse.min_sides = 3;
  return {finest, middle, coarse};
}

// --lod: each distinct plant of FILE (a scene, or one tree or plant at the origin) meshed at
// every resolution and flattened, the leaves ordered by --seed; the scene's obstacles (near the
// plants when `near_plants`) and those of `obstacles_file` drawn as they are.
graphics::LodScene load_lod_scene(const std::string& path, const std::string& format,
                                  const graphics::MeshOptions& options,
                                  const graphics::LodOptions& lod, bool near_plants,
                                  const std::string& obstacles_file) {
  const InputKind kind = input_kind(path);
  if (kind == InputKind::kPvd) throw ValueError("--lod needs a scene, tree or plant file", path);
  graphics::SceneFile plants;
  std::optional<SceneDescription> description;
  std::optional<graphics::TriangleMesh> terrain;
  if (kind == InputKind::kScene) {
    description = read_landscape_scene(path, terrain);
    plants = graphics::scene_plants(description->plants);
  } else {
    plants.sources.push_back({path, -1.0, default_mtg_tree_options()});
    plants.instances.emplace_back();
  }
  graphics::LodScene scene;
  std::vector<graphics::InstancedMesh> finest;
  for (const auto& source : plants.sources) {
    std::vector<graphics::TriangleMesh> resolutions;
    for (const auto& o : lod_resolutions(options)) {
      // A scene's plant files are read by their extension, as place_plants does.
      const std::string f = kind == InputKind::kScene ? std::string() : format;
      resolutions.push_back(
          load_part(source.path, input_kind(source.path), f, source.age, o, {}, source.mtg)
              .flatten());
    }
    // Reynolds 3.3: at the coarse switch, the key distance here, the highest level of branches
    // is removed (the leaves stay).
    resolutions.back() = graphics::without_highest_bark_orders(resolutions.back(), 1);
    finest.push_back(graphics::InstancedMesh::single(resolutions.front()));
    scene.plants.push_back(graphics::make_lod_plant(resolutions, lod, options.foliage_seed));
  }
  for (const auto& inst : plants.instances) {
    scene.placements.push_back(
        {inst.source, inst.linear().cast<float>(), inst.position.cast<float>()});
  }
  // Obstacles cropped against the plants at their finest, then kept as the fixed mesh.
  graphics::InstancedMesh placed = graphics::place_parts(finest, scene.placements);
  const std::size_t plant_meshes = placed.meshes.size();
  if (description && !description->obstacles.empty()) {
    add_scene_obstacles(placed, environment::scene_from_description(*description), path,
                        near_plants && !description->plants.empty());
  }
  if (!obstacles_file.empty()) {
    add_scene_obstacles(placed, environment::read_scene_file(obstacles_file), obstacles_file,
                        near_plants);
  }
  add_terrain(placed, terrain);
  for (const auto& inst : placed.instances) {
    if (inst.mesh < plant_meshes) continue;
    graphics::MeshInstance fixed = inst;
    fixed.mesh = static_cast<std::uint32_t>(scene.fixed.meshes.size());
    scene.fixed.meshes.push_back(placed.meshes[inst.mesh]);
    scene.fixed.instances.push_back(fixed);
  }
  return scene;
}

// --lod-distance, or 40 times the largest placed plant's bounding radius: the distance beyond
// which plants take the coarsest mesh; every leaf is drawn up to an eighth of it.
graphics::LodOptions lod_options(const graphics::LodScene& scene, double distance_m) {
  graphics::LodOptions o;
  if (distance_m <= 0.0) {
    double radius = 0.0;
    for (const auto& p : scene.placements) {
      radius = std::max(radius, scene.plants[p.part].sphere.radius *
                                    static_cast<double>(p.linear.colwise().norm().maxCoeff()));
    }
    distance_m = 40.0 * std::max(radius, 0.05);
  }
  o.max_distance_m = distance_m;
  o.prune_distance_m = distance_m / 8.0;
  return o;
}

nlohmann::json instancing_json(const graphics::InstancedMesh& m) {
  Eigen::Vector3f lo, hi;
  m.bounds(lo, hi);
  return {{"meshes", m.meshes.size()},
          {"instances", m.instances.size()},
          {"stored_triangles", m.stored_triangle_count()},
          {"bounds", {{"min", {lo.x(), lo.y(), lo.z()}}, {"max", {hi.x(), hi.y(), hi.z()}}}}};
}

// An L-system (.l) drawn for render, mesh and view: explicitly, or by instancing with
// --compressed. `pixels` > 0 (pictures): substructures smaller than a pixel of a picture that many
// pixels across drawn as their chord; 0: every substructure exact.
LsystemDrawing draw_lsystem_file(const std::string& file, const LsystemDrawArguments& arguments,
                                 int pixels) {
  return draw_lsystem(lsystem_draw_source(file, arguments), arguments.compressed,
                      pixels > 0 ? -1.0 : 0.0, pixels);
}

// --max-order and --merge-collinear reduce trees and compressed plants (in scenes too); an
// L-system is written as a plant first, and the per-plant --lod meshes every plant whole.
void check_graph_lod(const GraphLodArguments& arguments, const std::vector<std::string>& files,
                     bool per_plant_lod) {
  if (!arguments.lod().active()) return;
  if (per_plant_lod)
    throw ValueError("--max-order and --merge-collinear do not combine with --lod");
  for (const auto& f : files) {
    if (input_kind(f) == InputKind::kLsystem) {
      throw ValueError(
          "--max-order and --merge-collinear apply to trees and compressed plants: write the "
          "L-system as a plant first (fspm lsystem derive FILE --compressed -o PLANT.ctree)",
          f);
    }
  }
}

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

// --axis-subdivisions S of mesh, render and view (MeshOptions::axis_subdivisions).
void add_axis_subdivisions_option(CLI::App* app, int& subdivisions) {
  app->add_option("--axis-subdivisions", subdivisions,
                  "Rings per internode along each axis, on a cubic B-spline through the joints "
                  "(Pirk eq. 6.7): branches rounded at close range (separate junctions)")
      ->check(CLI::Range(1, graphics::kMaxAxisSubdivisions))
      ->capture_default_str();
}

// The mesh options of the mesh command's flags.
graphics::MeshOptions mesh_options(const MeshCommand& c) {
  graphics::MeshOptions options;
  set_leaves(options, c.leaves, c.foliage, c.seed);
  options.edge_length_m = c.edge_length_m;
  options.max_sides = c.max_sides;
  options.axis_subdivisions = c.axis_subdivisions;
  options.junctions = graphics::junction_mode_from_name(c.junctions);
  options.reynolds_width = c.reynolds_width;
  return options;
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
  const SkinnedOutput out = write_wind_glb(tree, options, c.wind, c.animate_s, c.seed, c.out);
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
                             ? greenlab::reconstruct(load_compressed(c.tree, kind), ro)
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
    mesh = mesh_lsystem(drawing, options);
  } else {
    mesh = load_instanced(c.tree, c.format, options, false, c.graph_lod.lod());
  }
  if (c.leaves) report_missing_leaves(mesh, c.tree);
  if (!c.obstacles.empty()) {
    add_scene_obstacles(mesh, environment::read_scene_file(c.obstacles), c.obstacles, false);
  }
  j["obstacle_triangles"] = obstacle_triangle_count(mesh);
  graphics::write_mesh(mesh, c.out);
  j["vertices"] = mesh.vertex_count();
  j["triangles"] = mesh.triangle_count();
  j.update(instancing_json(mesh));
}

// The folder fspm crown wrote (OUT/ holding crown.glb) stands for its crown, as in scene files.
std::string resolve_crown_folder(const std::string& path) {
  const std::filesystem::path crown = std::filesystem::path(path) / kCrownMeshName;
  const bool folder =
      std::filesystem::is_directory(path) && std::filesystem::is_regular_file(crown);
  return folder ? crown.string() : path;
}

void run_mesh(MeshCommand c) {
  c.tree = resolve_crown_folder(c.tree);
  refuse_overwriting_input(c.out, {c.tree, c.obstacles});
  const auto t0 = std::chrono::steady_clock::now();
  const graphics::MeshFormat format = graphics::mesh_format_for(c.out);
  const InputKind kind = input_kind(c.tree);
  check_mesh_request(c, format, kind);
  const graphics::MeshOptions options = mesh_options(c);
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

// --wind-time: one tree posed at that time of its wind animation, framed as at rest.
graphics::InstancedMesh wind_frame(const RenderCommand& c, const graphics::MeshOptions& options,
                                   graphics::RenderOptions& render) {
  if (input_kind(c.tree) != InputKind::kTree) {
    throw ValueError("--wind-time needs one tree file (.tree, .treeb, .nwk, .mtg)", c.tree);
  }
  WindFrame f =
      posed_in_wind(read_tree_file(c.tree, c.format), options, c.wind, c.wind_time_s, c.seed);
  render.frame = f.frame;
  return graphics::InstancedMesh::single(std::move(f.mesh));
}

// fspm render --lod: the plants chosen per instance for the render's camera.
void run_lod_render(const RenderCommand& c, const graphics::MeshOptions& mesh_options,
                    const graphics::RenderOptions& options,
                    std::chrono::steady_clock::time_point t0) {
  if (c.wind_time_s >= 0.0 || !c.color_by.empty() || !c.frame.empty()) {
    throw ValueError("--lod does not combine with --wind-time, --color-by or --frame");
  }
  const graphics::LodScene scene =
      load_lod_scene(c.tree, c.format, mesh_options, graphics::LodOptions{}, true, c.obstacles);
  const graphics::LodOptions lod = lod_options(scene, c.lod_distance_m);
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

// The mesh `fspm render` draws for a point set or .clusters file, or for any other input (an
// explicit --format names a tree format, whatever the extension).
graphics::InstancedMesh load_render_input(const std::string& path, const std::string& format,
                                          const graphics::MeshOptions& options,
                                          const LevelOfDetail& lod = {}) {
  if (format.empty()) {
    if (auto scan = load_scan_render_mesh(path, options)) {
      return graphics::InstancedMesh::single(std::move(*scan));
    }
  }
  if (input_kind(path) == InputKind::kTree) {
    // A skeleton at projected coordinates (fspm encode --skeleton keeps the input's frame) is
    // drawn relative to the kilometre below it, as its scan is: floats keep decimetres there and
    // the camera lost the tree without the ground plane's bounds.
    TreeGraph tree = read_tree_file(path, format, default_mtg_tree_options());
    recentre_for_render(tree);
    if (lod.active()) tree = reduce_tree(tree, lod);
    return graphics::InstancedMesh::single(graphics::mesh_tree(tree, options));
  }
  return load_instanced(path, format, options, true, lod);
}

// --frame: the bounds of another input, drawn with the same options, so that pictures of the
// stages of one tree (points, skeleton, clusters, reconstruction) share camera and ground.
Eigen::AlignedBox3f frame_of(const std::string& path, const graphics::MeshOptions& options) {
  const graphics::TriangleMesh mesh = load_render_input(path, "", options).flatten();
  if (mesh.empty()) throw ValueError("--frame: nothing to draw in the file", path);
  return {mesh.bbox_min(), mesh.bbox_max()};
}

#ifdef FSPM_HAVE_CROWN
// The crowns of a scene from fspm crown, each with the placements of its copies.
std::vector<graphics::ReliefCrown> scene_relief_crowns(const std::string& path) {
  std::optional<graphics::TriangleMesh> terrain;
  const graphics::SceneFile plants =
      graphics::scene_plants(read_landscape_scene(path, terrain).plants);
  std::vector<graphics::ReliefCrown> crowns;
  for (std::size_t s = 0; s < plants.sources.size(); ++s) {
    if (input_kind(plants.sources[s].path) != InputKind::kMesh) continue;
    graphics::ReliefCrown crown = read_relief_crown(plants.sources[s].path);
    crown.placements.clear();
    for (const auto& inst : plants.instances) {
      if (inst.source != s) continue;
      Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
      m.block<3, 3>(0, 0) = inst.linear().cast<float>();
      m.block<3, 1>(0, 3) = inst.position.cast<float>();
      crown.placements.push_back(m);
    }
    crowns.push_back(std::move(crown));
  }
  if (crowns.empty()) {
    throw ValueError("--ray-cast: the scene places no crown from fspm crown", path);
  }
  return crowns;
}
#endif

// What --ray-cast draws for one crown file from fspm crown or one scene: the crowns, drawn by
// relief-mapped ray casting of their cubemaps (Argudo 5.1), and everything else as meshes (the
// crowns' trunks, the scene's other plants, obstacles and terrain).
struct RayCastInput {
  std::vector<graphics::ReliefCrown> crowns;
  graphics::InstancedMesh meshes;
};

RayCastInput load_ray_cast_input(const std::vector<std::string>& paths,
                                 const graphics::MeshOptions& mesh_options) {
  const InputKind kind = paths.size() == 1 ? input_kind(paths[0]) : InputKind::kTree;
  if (kind != InputKind::kMesh && kind != InputKind::kScene) {
    throw ValueError(
        "--ray-cast draws the crowns of one crown file from fspm crown (its .glb or "
        ".obj) or of one scene");
  }
#ifdef FSPM_HAVE_CROWN
  RayCastInput in;
  if (kind == InputKind::kMesh) {
    in.crowns = {read_relief_crown(paths[0])};
    in.meshes = graphics::InstancedMesh::single(without_crown(read_placed_mesh(paths[0])));
  } else {
    in.crowns = scene_relief_crowns(paths[0]);
    in.meshes = load_scene(paths[0], mesh_options, true, {}, true);
  }
  return in;
#else
  (void)mesh_options;
  throw ValueError("fspm was built without the crown module (OpenImageIO): no --ray-cast");
#endif
}

void run_render(RenderCommand c) {
  c.tree = resolve_crown_folder(c.tree);
  refuse_overwriting_input(c.out, {c.tree, c.obstacles, c.frame});
  const auto t0 = std::chrono::steady_clock::now();
  graphics::RenderOptions options;
  options.view = c.view;
  graphics::parse_size(c.size, options.width, options.height);
  options.color_by = c.color_by;
  options.ground = !c.no_ground;
  options.ortho_height_m = c.ortho_height_m;
  if (!graphics::render_available()) {
    throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
  }
  graphics::check_image_path(c.out);
  graphics::MeshOptions mesh_options;
  set_leaves(mesh_options, c.leaves, c.foliage, c.seed);
  mesh_options.edge_length_m = c.edge_length_m;
  mesh_options.axis_subdivisions = c.axis_subdivisions;
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
    if (c.wind_time_s >= 0.0 || !c.color_by.empty()) {
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
    mesh = mesh_lsystem(drawing, mesh_options);
  } else {
    mesh = load_render_input(c.tree, c.format, mesh_options, c.graph_lod.lod());
  }
  if (!c.frame.empty()) options.frame = frame_of(c.frame, mesh_options);
  if (c.leaves) report_missing_leaves(mesh, c.tree);
  if (!c.color_by.empty()) {
    for (const auto& m : mesh.meshes) (void)m.attribute(c.color_by);  // unknown: ValueError
  }
  // Obstacles take 0 for every attribute; the renderer draws them in stone all the same.
  if (!c.obstacles.empty()) {
    add_scene_obstacles(mesh, environment::read_scene_file(c.obstacles), c.obstacles, true);
  }
  const std::size_t obstacle_triangles = obstacle_triangle_count(mesh);
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

// One FILE of `fspm view`, loaded once and meshed at each growth step.
struct ViewSource {
  std::string path;
  InputKind kind = InputKind::kTree;
  TreeGraph tree;
  CompressedTreeGraph graph;
  LsystemDrawing drawing;       // an L-system, drawn once
  graphics::TriangleMesh mesh;  // a crown from fspm crown, read once
  LevelOfDetail lod;
  // With --stages: the tree's developmental model (Pirk 5), whose stage at time `age` is drawn.
  std::shared_ptr<const stages::DevelopmentalModel> model;

  // `age`: plant age for compressed graphs, latest birth time for trees, the stage's time in
  // (0, 1] with --stages, ignored for scenes; infinity = everything.
  graphics::InstancedMesh at(double age, const graphics::MeshOptions& options,
                             const std::string& format) const {
    if (kind == InputKind::kScene) return load_scene(path, options, true, lod);
    if (is_compressed(kind)) {
      return mesh_compressed(graph, std::isinf(age) ? -1.0 : age, options, lod);
    }
    if (kind == InputKind::kLsystem) return mesh_lsystem(drawing, options);
    if (kind == InputKind::kMesh) return graphics::InstancedMesh::single(mesh);
    if (model) {
      return graphics::InstancedMesh::single(
          graphics::mesh_tree(model->stage(std::isinf(age) ? 1.0 : age), options));
    }
    graphics::MeshOptions o = options;
    o.max_birth_time = age;
    (void)format;
    return graphics::InstancedMesh::single(graphics::mesh_tree(tree, o));
  }
};

// Default growth steps of a compressed plant: whole cycles 1..final age, at most 20.
std::vector<double> plant_ages(const CompressedTreeGraph& g) {
  std::vector<double> ages;
  const double last = std::floor(g.final_age);
  const double step = std::max(1.0, std::ceil(last / 20.0));
  for (double a = last; a >= 1.0; a -= step) ages.push_back(a);
  if (ages.empty()) ages.push_back(g.final_age);
  std::reverse(ages.begin(), ages.end());
  return ages;
}

// Every file meshed at every age (instanced), placed side by side along x with a gap of a
// tenth of the widest.
std::vector<graphics::InstancedMesh> view_steps(const std::vector<ViewSource>& sources,
                                                const std::string& format,
                                                const std::vector<double>& ages,
                                                const graphics::MeshOptions& options) {
  std::vector<graphics::PartPlacement> placements;
  float x = 0.0f;
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const graphics::InstancedMesh full =
        sources[i].at(std::numeric_limits<double>::infinity(), options, format);
    Eigen::Vector3f lo, hi;
    full.bounds(lo, hi);
    const float width = hi.x() - lo.x();
    graphics::PartPlacement p;
    p.part = i;
    p.translation.x() = full.instances.empty() ? x : x - lo.x();
    placements.push_back(p);
    x += width * 1.1f + 0.1f;
  }
  std::vector<graphics::InstancedMesh> steps;
  for (double age : ages) {
    std::vector<graphics::InstancedMesh> parts;
    for (const auto& s : sources) parts.push_back(s.at(age, options, format));
    steps.push_back(graphics::place_parts(parts, placements));
  }
  return steps;
}

// fspm view --lod: one scene (or tree, or plant) with its plants chosen per instance each frame.
void run_lod_view(const ViewCommand& c, const graphics::ViewerOptions& options,
                  std::chrono::steady_clock::time_point t0) {
  if (c.trees.size() != 1 || !c.ages.empty()) {
    throw ValueError("--lod shows one scene, tree or plant file, without --ages");
  }
  graphics::MeshOptions mesh_options;
  set_leaves(mesh_options, c.leaves, c.foliage, c.seed);
  mesh_options.axis_subdivisions = c.axis_subdivisions;
  const graphics::LodScene scene =
      load_lod_scene(c.trees[0], c.format, mesh_options, graphics::LodOptions{}, true, "");
  graphics::LodOptions lod = lod_options(scene, c.lod_distance_m);
  // Impostors where expression 2 would cull (the renders keep the coarsest mesh there).
  lod.impostor_distance_m = c.no_impostors ? 0.0 : lod.max_distance_m;
  graphics::ViewerOptions with_terrain = options;
  // A terrain is the ground: no plane under it.
  if (input_kind(c.trees[0]) == InputKind::kScene &&
      read_scene_description(c.trees[0]).terrain.has_value()) {
    with_terrain.ground = false;
  }
  if (!c.screenshot.empty()) rerun_under_xvfb_if_needed();
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
                {"screenshot", c.screenshot},
                {"seconds", seconds_since(t0)}});
  }
}

graphics::ViewerOptions viewer_options(const ViewCommand& c) {
  graphics::ViewerOptions options;
  graphics::parse_size(c.size, options.width, options.height);
  options.color_by = c.color_by;
  options.screenshot = c.screenshot;
  // --frames: before the screenshot, or, without one, before the window closes by itself.
  options.frames = c.frames > 0 ? c.frames : 1;
  if (c.screenshot.empty()) options.close_after_frames = c.frames;
  options.shadows = !c.no_shadows;
  options.panel = !c.no_panel;
  options.ground = !c.no_ground;
  options.pitch_deg = c.pitch_deg;
  options.yaw_deg = c.yaw_deg;
  if (!c.look_at.empty()) options.look_at = {c.look_at[0], c.look_at[1], c.look_at[2]};
  options.camera_distance_m = c.distance_m;
  options.shadow_cascades = c.shadow_cascades;
  options.tessellation_max_level = c.tessellate;
  options.tessellation_distance_m = c.tessellation_distance_m;
  options.tessellation_on_cpu = c.tessellate_on_cpu;
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

std::vector<ViewSource> read_view_sources(const ViewCommand& c, int size_px,
                                          std::vector<double>& ages) {
  std::vector<ViewSource> sources;
  for (const auto& path : c.trees) {
    ViewSource s;
    s.path = path;
    s.kind = input_kind(path);
    s.lod = c.graph_lod.lod();
    if (is_compressed(s.kind)) {
      s.graph = load_compressed(path, s.kind);
      if (ages.empty()) ages = plant_ages(s.graph);
    } else if (s.kind == InputKind::kTree) {
      s.tree = read_tree_file(path, c.format);
      if (s.lod.active()) s.tree = reduce_tree(s.tree, s.lod);
      if (c.stages > 0) s.model = std::make_shared<const stages::DevelopmentalModel>(s.tree);
    } else if (s.kind == InputKind::kLsystem) {
      s.drawing = draw_lsystem_file(path, c.lsystem, size_px);
    } else if (s.kind == InputKind::kMesh) {
      s.mesh = read_placed_mesh(path);
    } else {
      (void)graphics::read_scene_file(path);  // bad scene: error before any window
    }
    sources.push_back(std::move(s));
  }
  return sources;
}

// The meshes of every age step, and a far level of detail: rings four times coarser, at most
// six sides. Returns the far meshes' ring edge length.
double mesh_view_steps(const ViewCommand& c, const std::vector<ViewSource>& sources,
                       std::vector<double>& ages, std::vector<graphics::InstancedMesh>& steps,
                       std::vector<graphics::InstancedMesh>& far) {
  if (ages.empty()) ages.push_back(std::numeric_limits<double>::infinity());
  std::sort(ages.begin(), ages.end());
  graphics::MeshOptions mesh_options;
  set_leaves(mesh_options, c.leaves, c.foliage, c.seed);
  mesh_options.max_sides = c.max_sides;
  mesh_options.min_sides = std::min(mesh_options.min_sides, c.max_sides);
  mesh_options.axis_subdivisions = c.axis_subdivisions;
  steps = view_steps(sources, c.format, ages, mesh_options);
  graphics::MeshOptions coarse = mesh_options;
  coarse.axis_subdivisions = 1;  // far away: straight internodes
  coarse.edge_length_m *= 4.0;
  coarse.max_sides = std::min(6, c.max_sides);
  coarse.min_sides = 3;
  far = view_steps(sources, c.format, ages, coarse);
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
              {"screenshot", c.screenshot},
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
  graphics::MeshOptions mesh_options;
  set_leaves(mesh_options, c.leaves, c.foliage, c.seed);
  auto wind = std::make_shared<graphics::ViewerWind>();
  wind->mesh = skinnable_mesh(tree, mesh_options);
  wind->skin = graphics::skin_mesh(tree, wind->mesh);
  wind->wind = wind_options(c.wind_args, c.wind_args.duration_s, c.seed);
  if (!c.color_by.empty()) (void)wind->mesh.attribute(c.color_by);
  const std::vector<graphics::InstancedMesh> steps{graphics::InstancedMesh::single(wind->mesh)};
  options.wind = std::move(wind);
  if (!c.screenshot.empty()) rerun_under_xvfb_if_needed();
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
  graphics::MeshOptions mesh_options;
  set_leaves(mesh_options, c.leaves, c.foliage, c.seed);
  RayCastInput in = load_ray_cast_input(c.trees, mesh_options);
  options.relief_crowns = std::move(in.crowns);
  const std::vector<graphics::InstancedMesh> steps{std::move(in.meshes)};
  if (!c.screenshot.empty()) rerun_under_xvfb_if_needed();
  const std::vector<double> ages{std::numeric_limits<double>::infinity()};
  const graphics::ViewerStats stats = graphics::run_instanced_viewer(steps, ages, options);
  if (c.json) print_view_json(c, steps, stats, t0);
}

void run_view(ViewCommand c) {
  const auto t0 = std::chrono::steady_clock::now();
  for (std::string& path : c.trees) path = resolve_crown_folder(path);
  if (!graphics::viewer_available()) {
    throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
  }
  graphics::ViewerOptions options = viewer_options(c);
  if (c.stages > 0) options.step_label = "time";
  if (!c.screenshot.empty()) graphics::check_image_path(c.screenshot);
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
  if (!c.color_by.empty()) {
    for (const auto& step : steps) {
      for (const auto& m : step.meshes) (void)m.attribute(c.color_by);
    }
  }
  if (!c.screenshot.empty()) rerun_under_xvfb_if_needed();
  const graphics::ViewerStats stats = graphics::run_instanced_viewer(steps, ages, options, far);
  if (c.json) print_view_json(c, steps, stats, t0);
}

// --foliage and --seed of the commands that draw leaf clusters.
void add_foliage_options(CLI::App* command, std::string& foliage, std::uint64_t& seed) {
  command
      ->add_option("--foliage", foliage,
                   "Leaf clusters of grown and adapted trees with --leaves: leaves (a cloud of "
                   "small leaves) or volumes (translucent crown spheres)")
      ->capture_default_str();
  command->add_option("--seed", seed, "Seed of the leaf placement in clusters")
      ->check(number_in(0, kMaxSeed))
      ->capture_default_str();
}

// --lod and --lod-distance of render and view.
void add_lod_options(CLI::App* command, bool& lod, double& distance_m) {
  command->add_flag("--lod", lod,
                    "Level of detail per plant: skip plants outside the view, three mesh "
                    "resolutions by distance and size, fewer (larger) leaves far away");
  command
      ->add_option("--lod-distance", distance_m,
                   "With --lod: distance in m from which plants take the coarsest mesh (default "
                   "40 times the largest plant's bounding radius)")
      ->check(positive_number(1e9));
}

void add_ray_cast_flag(CLI::App* command, bool& ray_cast) {
  command->add_flag(
      "--ray-cast", ray_cast,
      "Draw the crowns from fspm crown (a crown's .glb or .obj, or a scene placing them) by "
      "relief-mapped ray casting of their cubemaps (Argudo 5.1) instead of triangles");
}

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
  m->add_flag("--leaves", mesh->leaves, "Mesh leaf nodes as quads, leaf clusters as foliage");
  add_foliage_options(m, mesh->foliage, mesh->seed);
  m->add_option("--ages", mesh->ages,
                "Ages of a .pvd growth sequence (default: the birth times, at most 20)")
      ->delimiter(',');
  m->add_option("--edge-length", mesh->edge_length_m,
                "Target ring edge length in m (ring resolution from radius)")
      ->check(positive_number(1e6));
  m->add_option("--max-sides", mesh->max_sides, "Most sides of a ring")->check(CLI::Range(3, 256));
  add_axis_subdivisions_option(m, mesh->axis_subdivisions);
  m->add_option("--junctions", mesh->junctions,
                "separate (a closed tube per chain) or continuous (Reynolds: one surface through "
                "branch points, bone weights per vertex)")
      ->capture_default_str();
  m->add_flag("--reynolds-width", mesh->reynolds_width,
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
  m->callback([mesh] { run_mesh(*mesh); });
}

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
  r->add_option("--color-by", render->color_by,
                "Colour by a vertex attribute (age, birth_time, order, physiological_age or a "
                "tree attribute) with a scalar bar");
  add_enum_option(r, "--view", render->view, kViews, view_name, "Camera direction");
  r->add_option("--size", render->size, "WIDTHxHEIGHT in pixels")->capture_default_str();
  r->add_flag("--leaves", render->leaves, "Show leaves and leaf clusters");
  add_foliage_options(r, render->foliage, render->seed);
  r->add_flag("--no-ground", render->no_ground, "Leave out the ground plane");
  add_axis_subdivisions_option(r, render->axis_subdivisions);
  r->add_option("--edge-length", render->edge_length_m, "Target ring edge length in m")
      ->check(positive_number(1e6));
  r->add_option("--ortho-height", render->ortho_height_m,
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
  r->callback([render] { run_render(*render); });
}

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
  v->add_option("--color-by", view->color_by, "Colour by a vertex attribute");
  v->add_flag("--leaves", view->leaves, "Show leaves and leaf clusters");
  add_foliage_options(v, view->foliage, view->seed);
  v->add_flag("--no-shadows", view->no_shadows, "Start without shadows");
  v->add_flag("--no-panel", view->no_panel,
              "Hide the controls panel (growth step, shadows, level-of-detail distance, colour "
              "attribute, frame time and triangles)");
  v->add_option("--pitch-deg", view->pitch_deg,
                "Starting camera elevation above the horizontal, degrees (a few: a low view)")
      ->check(CLI::Range(-89.0, 89.0))
      ->capture_default_str();
  v->add_option("--yaw-deg", view->yaw_deg,
                "Starting camera azimuth, degrees counter-clockwise from +x (the eye's direction "
                "from the point looked at)")
      ->check(CLI::Range(-360.0, 360.0));
  v->add_option("--look-at", view->look_at,
                "Starting point looked at, X,Y,Z in m (default: the centre of the scene)")
      ->delimiter(',')
      ->expected(3);
  v->add_option("--distance", view->distance_m,
                "Starting camera distance from the point looked at, m (default: the whole scene "
                "in view)")
      ->check(positive_number(1e9));
  v->add_option("--shadow-cascades", view->shadow_cascades,
                "Cascaded shadow maps: N maps over slices of the view up to three camera "
                "distances away, nearest first, before the one map of the whole scene (sharp "
                "shadows near the camera over a landscape; one redrawn a frame while the camera "
                "moves; also on the panel)")
      ->check(CLI::Range(0, 4))
      ->capture_default_str();
  v->add_option("--size", view->size, "Window WIDTHxHEIGHT")->capture_default_str();
  v->add_option("--screenshot", view->screenshot,
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
  add_axis_subdivisions_option(v, view->axis_subdivisions);
  v->add_option("--max-sides", view->max_sides,
                "Most sides of a ring (4: Reynolds' coarse branch mesh, for --tessellate)")
      ->check(CLI::Range(3, 256))
      ->capture_default_str()
      ->excludes(lod);
  CLI::Option* tessellate =
      v->add_option("--tessellate", view->tessellate,
                    "Tessellate the opaque triangles up to level L (Reynolds' expression 2: finer "
                    "near the camera and for edges longer on the screen), new vertices on curved "
                    "PN triangles; tessellation shaders where the context has them, else on the "
                    "CPU")
          ->check(CLI::Range(1.0, 64.0))
          ->excludes(lod)
          ->excludes(v->get_option("--wind"));
  v->add_option("--tessellation-distance", view->tessellation_distance_m,
                "D_max of expression 2 in m (default 4 times the starting camera distance)")
      ->check(positive_number(1e9))
      ->needs(tessellate);
  v->add_flag("--tessellate-on-cpu", view->tessellate_on_cpu,
              "Tessellate on the CPU even where tessellation shaders exist (one level for the "
              "scene, from the starting camera distance)")
      ->needs(tessellate);
  add_lsystem_draw_options(v, view->lsystem);
  add_graph_lod_options(v, view->graph_lod);
  v->add_flag("--json", view->json, "Machine-readable JSON on stdout (frame time)");
  v->callback([view] { run_view(*view); });
}

}  // namespace

void add_graphics_commands(CLI::App& app) {
  add_mesh_command(app);
  add_render_command(app);
  add_view_command(app);
}

}  // namespace fspm::cli
