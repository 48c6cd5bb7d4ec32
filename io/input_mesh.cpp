#include "io/input_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "environment/scene_file.hpp"
#include "fspm/error.hpp"
#include "fspm/scene_reader.hpp"
#include "fspm/tree_file.hpp"
#include "graphics/landscape.hpp"
#include "graphics/scene_file.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"
#include "io/placed_mesh.hpp"
#include "io/scan_render_mesh.hpp"
#include "io/scene_obstacles.hpp"

namespace fspm::io {

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
                                  graphics::MeshOptions options, const LevelOfDetail& lod,
                                  const MtgTreeOptions& mtg) {
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

namespace {

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

}  // namespace

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
                                   bool near_plants, const LevelOfDetail& lod,
                                   bool crowns_ray_cast) {
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
                                       const LevelOfDetail& lod) {
  const InputKind kind = input_kind(path);
  if (kind == InputKind::kScene) return load_scene(path, options, near_plants, lod);
  return load_part(path, kind, format, -1.0, options, lod);
}

// The mesh `fspm render` draws for a point set or .clusters file, or for any other input (an
// explicit --format names a tree format, whatever the extension).
graphics::InstancedMesh load_render_input(const std::string& path, const std::string& format,
                                          const graphics::MeshOptions& options,
                                          const LevelOfDetail& lod) {
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

}  // namespace fspm::io
