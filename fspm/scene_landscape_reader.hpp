#pragma once
// The terrain and the population of a scene file (docs/formats.md, "Terrains and populations"):
// a heightfield image and plants spread over it from a class map. Part of the scene reader.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "fspm/json_fields.hpp"
#include "fspm/scene_description.hpp"

namespace fspm {

// {"heightfield", "metres_per_pixel", "height_scale_m", "stride"} at `path`; the image is
// resolved against `base`.
SceneTerrain read_scene_terrain(const JsonFields& f, const nlohmann::json& t,
                                const std::string& path, const std::filesystem::path& base);

// {"map", "classes", "min_distance_m", "count", "seed", "scale_jitter"} at `path`; the map and
// the plant files are resolved against `base`.
ScenePopulation read_scene_population(const JsonFields& f, const nlohmann::json& p,
                                      const std::string& path, const std::filesystem::path& base);

}  // namespace fspm
