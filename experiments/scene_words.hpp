#pragma once
// A scene file in words for a report: each obstacle's kind, size and distance from the plant,
// so a reader learns that the wall is 4 m high and 2 m away without opening the file.
#include <string>

namespace fspm::experiments {

// "a wall 4 m high, 0.2 m thick and 40 m long, 2 m from the plant; the ground at z = 0 m".
// Distances are horizontal, from the vertical axis through (0, 0), where the grow and adapt
// models stand their tree. Empty when the scene has no obstacle or cannot be read (the runs
// report that error themselves).
std::string scene_in_words(const std::string& scene_path);

}  // namespace fspm::experiments
