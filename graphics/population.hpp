#pragma once
// Plants spread over a terrain from a class map (Argudo 2014, 6.2): blue-noise sites at a
// minimum distance (poisson_disk.hpp), each kept with its class's density, given one of the
// class's plant files by their probabilities, set on the terrain (bilinear height), turned
// about z uniformly and scaled by a factor uniform in [1 - jitter, 1 + jitter]. The same
// population, terrain, map and generator state give the same plants.
#include <random>
#include <vector>

#include "fspm/scene_description.hpp"
#include "graphics/float_image.hpp"
#include "graphics/heightfield.hpp"

namespace fspm::graphics {

// The class map's grey level (0-255) at (x, y): the map stretched over the terrain's extent,
// the pixel containing the point (row 0 at the north edge).
int class_value_at(const FloatImage& map, const Heightfield& terrain, double x_m, double y_m);

// The placed plants. `class_map` may be null only when the population has a single class.
// Throws ValueError for a population without classes or with a class without plants.
std::vector<ScenePlant> place_population(const ScenePopulation& population,
                                         const Heightfield& terrain, const FloatImage* class_map,
                                         std::mt19937_64& rng);

}  // namespace fspm::graphics
