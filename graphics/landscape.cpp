#include "graphics/landscape.hpp"

#include <random>

#include "graphics/heightfield.hpp"
#include "graphics/population.hpp"

namespace fspm::graphics {

Landscape scene_landscape(const SceneDescription& scene) {
  Landscape out;
  if (!scene.terrain) return out;
  const SceneTerrain& t = *scene.terrain;
  const Heightfield terrain(read_float_image(t.heightfield), t.metres_per_pixel, t.height_scale_m,
                            t.heightfield);
  out.terrain = heightfield_mesh(terrain, t.stride);
  if (scene.population) {
    std::optional<FloatImage> map;
    if (!scene.population->map.empty()) map = read_float_image(scene.population->map);
    std::mt19937_64 rng(scene.population->seed);
    out.plants = place_population(*scene.population, terrain, map ? &*map : nullptr, rng);
  }
  return out;
}

}  // namespace fspm::graphics
