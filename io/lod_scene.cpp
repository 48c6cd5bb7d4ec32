#include "io/lod_scene.hpp"

#include <algorithm>
#include <optional>

#include "environment/scene_file.hpp"
#include "fspm/error.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/landscape.hpp"
#include "graphics/scene_file.hpp"
#include "graphics/tessellation_level.hpp"
#include "io/input_kind.hpp"
#include "io/input_mesh.hpp"
#include "io/scene_obstacles.hpp"

namespace fspm::io {
namespace {

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

}  // namespace

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

}  // namespace fspm::io
