#pragma once
// Writes a scene in the current layout ("fspm_scene": 2, docs/formats.md); what `fspm scene
// upgrade` does to files in an earlier layout. Only what the scene sets is written, so defaults
// stay defaults.
#include <nlohmann/json.hpp>
#include <string>

#include "fspm/scene_description.hpp"

namespace fspm {

// The scene as JSON, keys in the order of docs/formats.md; plant files relative to `directory`
// (the written file's; empty: the working directory).
nlohmann::ordered_json scene_description_json(const SceneDescription& scene,
                                              const std::string& directory);

// Writes atomically (no half-written file), one obstacle or plant a line; throws IoError when it
// cannot.
void write_scene_description(const SceneDescription& scene, const std::string& path);

}  // namespace fspm
