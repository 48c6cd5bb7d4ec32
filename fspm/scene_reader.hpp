#pragma once
// The one reader of scene files (JSON, docs/formats.md). It also reads the two earlier layouts:
// growth scenes with "occluders" (the ground among them) and plant scenes with
// "fspm_scene": 1 and "instances"; `fspm scene upgrade` rewrites them in the current layout.
#include <string>
#include <string_view>

#include "fspm/scene_description.hpp"

namespace fspm {

// Current layout version, written as "fspm_scene": 2.
inline constexpr int kSceneVersion = 2;

// Throws ParseError for malformed JSON (with line and column) and ValueError for a bad key or
// value, naming the file, the line, the JSON path and what was expected. Plant files are resolved
// against the directory of `file_name`.
SceneDescription parse_scene_description(std::string_view text,
                                         const std::string& file_name = "<scene>");
// Throws IoError when the file cannot be read.
SceneDescription read_scene_description(const std::string& path);

// True when `path` ends in .json (case-insensitive): commands taking a tree take it as a scene.
bool is_scene_path(const std::string& path);

}  // namespace fspm
