#include "graphics/population.hpp"

#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"
#include "graphics/poisson_disk.hpp"

namespace fspm::graphics {
namespace {

// The class of each grey level (nullptr: no plants there).
std::vector<const PopulationClass*> class_table(const ScenePopulation& population) {
  std::vector<const PopulationClass*> table(256, nullptr);
  for (const auto& c : population.classes) {
    if (c.plants.empty()) throw ValueError("a population class has no plants");
    table[static_cast<std::size_t>(std::clamp(c.value, 0, 255))] = &c;
  }
  return table;
}

// One of the class's plants by its probability (inverse of the cumulative distribution).
const PopulationPlant& choose_plant(const PopulationClass& c, double u) {
  double cumulative = 0.0;
  for (const auto& p : c.plants) {
    cumulative += p.probability;
    if (u < cumulative) return p;
  }
  return c.plants.back();  // rounding: the sum may fall short of 1 by a little
}

}  // namespace

int class_value_at(const FloatImage& map, const Heightfield& terrain, double x_m, double y_m) {
  const double fx = x_m / terrain.width_m();
  const double fy = 1.0 - y_m / terrain.depth_m();
  const int px = std::clamp(static_cast<int>(std::floor(fx * map.width)), 0, map.width - 1);
  const int py = std::clamp(static_cast<int>(std::floor(fy * map.height)), 0, map.height - 1);
  return std::clamp(static_cast<int>(std::lround(255.0 * map.at(px, py))), 0, 255);
}

std::vector<ScenePlant> place_population(const ScenePopulation& population,
                                         const Heightfield& terrain, const FloatImage* class_map,
                                         std::mt19937_64& rng) {
  if (population.classes.empty()) throw ValueError("a population needs at least one class");
  if (!class_map && population.classes.size() != 1) {
    throw ValueError("a population of several classes needs a class map");
  }
  const std::vector<const PopulationClass*> table = class_table(population);
  const auto class_at = [&](const Eigen::Vector2d& p) -> const PopulationClass* {
    if (!class_map) return &population.classes.front();
    return table[static_cast<std::size_t>(class_value_at(*class_map, terrain, p.x(), p.y()))];
  };
  PoissonDiskOptions o;
  o.width_m = terrain.width_m();
  o.depth_m = terrain.depth_m();
  o.min_distance_m = population.min_distance_m;
  o.max_count = population.count ? static_cast<std::size_t>(*population.count) : 0;
  std::vector<Eigen::Vector2d> sites;
  try {
    sites = poisson_disk_points(o, rng, [&](const Eigen::Vector2d& p) {
      const PopulationClass* c = class_at(p);
      return c ? c->density : 0.0;
    });
  } catch (const ValueError& e) {
    // Which setting of the scene made the grid too large.
    if (!e.file().empty()) throw;
    throw ValueError("population.min_distance_m " + std::to_string(population.min_distance_m) +
                     " m over a terrain of " + std::to_string(terrain.width_m()) + " x " +
                     std::to_string(terrain.depth_m()) + " m: " + e.message());
  } catch (const MemoryLimitError& e) {
    throw MemoryLimitError("population.min_distance_m " +
                           std::to_string(population.min_distance_m) + " m: " + e.message());
  }
  std::vector<ScenePlant> plants;
  plants.reserve(sites.size());
  for (const Eigen::Vector2d& s : sites) {
    const PopulationPlant& chosen = choose_plant(*class_at(s), unit_uniform(rng));
    ScenePlant plant;
    plant.file = chosen.file;
    plant.age = chosen.age;
    plant.position = {s.x(), s.y(), terrain.height_at(s.x(), s.y())};
    plant.rotation_deg.z() = 360.0 * unit_uniform(rng);
    plant.scale = 1.0 + population.scale_jitter * (2.0 * unit_uniform(rng) - 1.0);
    plants.push_back(plant);
  }
  return plants;
}

}  // namespace fspm::graphics
