#pragma once
// The obstacles of a scene file (docs/formats.md): sphere, cluster, box, wall, mesh and, in the
// earlier growth-scene layout, ground among them. Part of the scene reader.
#include <nlohmann/json.hpp>
#include <string>

#include "fspm/json_fields.hpp"
#include "fspm/scene_description.hpp"

namespace fspm {

// Appends the obstacle `o` at JSON path `path` to the scene (a "ground" entry, when `allow_ground`,
// becomes the scene's ground; there is at most one).
void read_scene_obstacle(const JsonFields& f, const nlohmann::json& o, const std::string& path,
                         bool allow_ground, SceneDescription& scene);

// The ground object {"z", "translucency", "solid"} at `path`.
SceneGround read_scene_ground(const JsonFields& f, const nlohmann::json& g,
                              const std::string& path);

}  // namespace fspm
