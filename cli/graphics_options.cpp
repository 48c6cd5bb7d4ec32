// What the graphics commands share: options, checks and the crowns drawn by ray casting.
#include "cli/graphics_options.hpp"

#include <spdlog/spdlog.h>

#include <optional>

#ifdef FSPM_HAVE_CROWN
#include "cli/crown_cubemaps_file.hpp"
#endif
#include "cli/enum_option.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "graphics/foliage.hpp"
#include "graphics/scene_file.hpp"
#include "io/input_kind.hpp"
#include "io/input_mesh.hpp"
#include "io/placed_mesh.hpp"

namespace fspm::cli {

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
    if (io::input_kind(f) == io::InputKind::kLsystem) {
      throw ValueError(
          "--max-order and --merge-collinear apply to trees and compressed plants: write the "
          "L-system as a plant first (fspm lsystem derive FILE --compressed -o PLANT.ctree)",
          f);
    }
  }
}

// --axis-subdivisions S of mesh, render and view (MeshOptions::axis_subdivisions).
void add_axis_subdivisions_option(CLI::App* app, graphics::MeshOptions& options) {
  app->add_option("--axis-subdivisions", options.axis_subdivisions,
                  "Rings per internode along each axis, on a cubic B-spline through the joints "
                  "(Pirk eq. 6.7): branches rounded at close range (separate junctions)")
      ->check(CLI::Range(1, graphics::kMaxAxisSubdivisions))
      ->capture_default_str();
}

// --leaves, --foliage and --seed of the commands that draw leaves and leaf clusters.
void add_leaves_options(CLI::App* command, graphics::MeshOptions& options,
                        const std::string& leaves_help) {
  command->add_flag("--leaves", options.leaves, leaves_help);
  add_enum_option(command, "--foliage", options.foliage.mode, graphics::kFoliageModeNames,
                  "Leaf clusters of grown and adapted trees with --leaves");
  command->add_option("--seed", options.foliage_seed, "Seed of the leaf placement in clusters")
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

#ifdef FSPM_HAVE_CROWN
namespace {

// The crowns of a scene from fspm crown, each with the placements of its copies.
std::vector<graphics::ReliefCrown> scene_relief_crowns(const std::string& path) {
  std::optional<graphics::TriangleMesh> terrain;
  const graphics::SceneFile plants =
      graphics::scene_plants(io::read_landscape_scene(path, terrain).plants);
  std::vector<graphics::ReliefCrown> crowns;
  for (std::size_t s = 0; s < plants.sources.size(); ++s) {
    if (io::input_kind(plants.sources[s].path) != io::InputKind::kMesh) continue;
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

}  // namespace
#endif

RayCastInput load_ray_cast_input(const std::vector<std::string>& paths,
                                 const graphics::MeshOptions& mesh_options) {
  const io::InputKind kind = paths.size() == 1 ? io::input_kind(paths[0]) : io::InputKind::kTree;
  if (kind != io::InputKind::kMesh && kind != io::InputKind::kScene) {
    throw ValueError(
        "--ray-cast draws the crowns of one crown file from fspm crown (its .glb or "
        ".obj) or of one scene");
  }
#ifdef FSPM_HAVE_CROWN
  RayCastInput in;
  if (kind == io::InputKind::kMesh) {
    in.crowns = {read_relief_crown(paths[0])};
    in.meshes = graphics::InstancedMesh::single(io::without_crown(io::read_placed_mesh(paths[0])));
  } else {
    in.crowns = scene_relief_crowns(paths[0]);
    in.meshes = io::load_scene(paths[0], mesh_options, true, {}, true);
  }
  return in;
#else
  (void)mesh_options;
  throw ValueError("fspm was built without the crown module (OpenImageIO): no --ray-cast");
#endif
}

}  // namespace fspm::cli
