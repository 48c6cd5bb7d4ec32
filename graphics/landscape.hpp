#pragma once
// The terrain and the population of a scene file (docs/formats.md, "Terrains and populations"):
// the heightfield meshed, the population's plants placed on it by a generator seeded with the
// population's seed. Renders and meshes add the terrain to the scene's obstacles and the plants
// to its placed plants.
#include <optional>
#include <vector>

#include "fspm/scene_description.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct Landscape {
  std::optional<TriangleMesh> terrain;  // material terrain
  std::vector<ScenePlant> plants;       // the population's, on the terrain
};

// Empty without a terrain. Throws IoError when an image cannot be read and ValueError for a
// heightfield smaller than 2 x 2 or with values that are not finite.
Landscape scene_landscape(const SceneDescription& scene);

}  // namespace fspm::graphics
