#pragma once
// Scene files (docs/formats.md) as the sky and occluders of light and growth: read by the one
// scene reader (fspm/scene_reader.hpp), then converted. Plants placed in the scene are not
// occluders and are left out here. Errors name the file, the line, the JSON path and what was
// expected.
#include <string>
#include <string_view>

#include "environment/scene.hpp"
#include "fspm/scene_description.hpp"

namespace fspm::environment {

// The sky and occluders of a scene description; defaults filled in (a cluster's translucency by
// Pirk eq. 4.4 from its gamma0 or the scene's).
Scene scene_from_description(const SceneDescription& description);

// Throws ParseError for malformed JSON and ValueError for values out of range.
Scene parse_scene_json(std::string_view text, const std::string& file_name = "<scene>");
// Throws IoError when the file cannot be read.
Scene read_scene_file(const std::string& path);

}  // namespace fspm::environment
