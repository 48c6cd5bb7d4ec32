#pragma once
// A scene, tree or plant prepared for per-plant level of detail (render and view --lod, Reynolds
// 3.3): each distinct plant meshed at three resolutions, the obstacles and terrain kept whole.
#include <string>

#include "graphics/instance_lod.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::io {

// Each distinct plant of `path` (a scene, or one tree or plant at the origin) meshed at the
// resolutions of `options` and rings four and sixteen times coarser, flattened, the leaves ordered
// by the foliage seed; the scene's obstacles (near the plants when `near_plants`) and those of
// `obstacles_file` drawn as they are. Throws ValueError for a .pvd.
graphics::LodScene load_lod_scene(const std::string& path, const std::string& format,
                                  const graphics::MeshOptions& options,
                                  const graphics::LodOptions& lod, bool near_plants,
                                  const std::string& obstacles_file);

// `distance_m`, or 40 times the largest placed plant's bounding radius when it is 0: the distance
// beyond which plants take the coarsest mesh; every leaf is drawn up to an eighth of it.
graphics::LodOptions lod_options(const graphics::LodScene& scene, double distance_m);

}  // namespace fspm::io
