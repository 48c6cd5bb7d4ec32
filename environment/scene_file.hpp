#pragma once
// Scene files (JSON, z up), documented in docs/environment.md. Errors name the file, the JSON path
// (or line and column for syntax errors) and what was expected.
#include <string>
#include <string_view>

#include "environment/scene.hpp"

namespace fspm::environment {

// Throws ParseError for malformed JSON and ValueError for values out of range.
Scene parse_scene_json(std::string_view text, const std::string& file_name = "<scene>");
// Throws IoError when the file cannot be read.
Scene read_scene_file(const std::string& path);

}  // namespace fspm::environment
