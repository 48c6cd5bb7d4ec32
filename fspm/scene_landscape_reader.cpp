#include "fspm/scene_landscape_reader.hpp"

#include <cmath>
#include <set>

namespace fspm {
namespace {

using nlohmann::json;

std::string resolved(const JsonFields& f, const json& o, const std::string& path, const char* key,
                     const std::string& what, const std::filesystem::path& base) {
  std::filesystem::path file = f.text(o, path, key, what);
  if (file.is_relative() && !base.empty()) file = base / file;
  return file.lexically_normal().string();
}

PopulationPlant read_population_plant(const JsonFields& f, const json& p, const std::string& path,
                                      const std::filesystem::path& base) {
  if (!p.is_object()) f.fail(path, "a plant object with file and probability", &p);
  f.check_keys(p, path, {"file", "probability", "age"});
  PopulationPlant plant;
  plant.file = resolved(f, p, path, "file", "a plant file (tree, .ctree or plant .toml)", base);
  plant.probability = f.number(p, path, "probability", 0, 1, "a probability in [0, 1]");
  plant.age = f.optional_number(p, path, "age", 0, 1e9, "an age >= 0");
  return plant;
}

PopulationClass read_population_class(const JsonFields& f, const json& c, const std::string& path,
                                      const std::filesystem::path& base) {
  if (!c.is_object()) f.fail(path, "a class object with value, density and plants", &c);
  f.check_keys(c, path, {"value", "density", "plants"});
  PopulationClass out;
  const double value =
      f.optional_number(c, path, "value", 0, 255, "a grey level in [0, 255]").value_or(0.0);
  if (value != std::floor(value)) f.fail(path + "/value", "a whole grey level", &c.at("value"));
  out.value = static_cast<int>(value);
  out.density = f.optional_number(c, path, "density", 0, 1, "a probability in [0, 1]").value_or(1);
  const std::string p = path + "/plants";
  if (!c.contains("plants") || !c.at("plants").is_array() || c.at("plants").empty()) {
    f.fail(p, "a non-empty array of plants", c.contains("plants") ? &c.at("plants") : nullptr);
  }
  double sum = 0.0;
  for (std::size_t i = 0; i < c.at("plants").size(); ++i) {
    out.plants.push_back(
        read_population_plant(f, c.at("plants")[i], p + "/" + std::to_string(i), base));
    sum += out.plants.back().probability;
  }
  if (std::abs(sum - 1.0) > 1e-6) {
    f.fail(p, "plant probabilities summing to 1, got " + std::to_string(sum));
  }
  return out;
}

}  // namespace

SceneTerrain read_scene_terrain(const JsonFields& f, const json& t, const std::string& path,
                                const std::filesystem::path& base) {
  if (!t.is_object()) f.fail(path, "an object with heightfield, metres_per_pixel", &t);
  f.check_keys(t, path, {"heightfield", "metres_per_pixel", "height_scale_m", "stride"});
  SceneTerrain terrain;
  terrain.heightfield =
      resolved(f, t, path, "heightfield", "a height image (.png, .tif, .exr)", base);
  terrain.metres_per_pixel =
      f.number(t, path, "metres_per_pixel", 1e-6, 1e6, "a pixel size in metres > 0");
  terrain.height_scale_m =
      f.optional_number(t, path, "height_scale_m", -1e6, 1e6, "metres per height unit")
          .value_or(1.0);
  const double stride =
      f.optional_number(t, path, "stride", 1, 1 << 16, "a whole stride >= 1").value_or(1.0);
  if (stride != std::floor(stride))
    f.fail(path + "/stride", "a whole stride >= 1", &t.at("stride"));
  terrain.stride = static_cast<int>(stride);
  return terrain;
}

ScenePopulation read_scene_population(const JsonFields& f, const json& p, const std::string& path,
                                      const std::filesystem::path& base) {
  if (!p.is_object()) f.fail(path, "an object with classes and min_distance_m", &p);
  f.check_keys(p, path, {"map", "classes", "min_distance_m", "count", "seed", "scale_jitter"});
  ScenePopulation pop;
  if (p.contains("map")) pop.map = resolved(f, p, path, "map", "a class map image", base);
  pop.min_distance_m = f.number(p, path, "min_distance_m", 1e-6, 1e6, "a distance in metres > 0");
  pop.count = f.optional_number(p, path, "count", 1, 1e8, "a plant count in [1, 1e8]");
  if (pop.count) *pop.count = std::floor(*pop.count);
  pop.seed = static_cast<std::uint64_t>(
      f.optional_number(p, path, "seed", 0, 9007199254740992.0, "a seed in [0, 2^53]")
          .value_or(1.0));
  pop.scale_jitter =
      f.optional_number(p, path, "scale_jitter", 0, 0.999, "a jitter in [0, 1)").value_or(0.0);
  const std::string c = path + "/classes";
  if (!p.contains("classes") || !p.at("classes").is_array() || p.at("classes").empty()) {
    f.fail(c, "a non-empty array of classes", p.contains("classes") ? &p.at("classes") : nullptr);
  }
  std::set<int> values;
  for (std::size_t i = 0; i < p.at("classes").size(); ++i) {
    const std::string ci = c + "/" + std::to_string(i);
    pop.classes.push_back(read_population_class(f, p.at("classes")[i], ci, base));
    if (!values.insert(pop.classes.back().value).second) {
      f.fail(ci + "/value", "a grey level no other class has");
    }
  }
  if (pop.map.empty() && pop.classes.size() != 1) {
    f.fail(c, "one class (several classes need a map)", &p.at("classes"));
  }
  return pop;
}

}  // namespace fspm
