#include "fspm/scene_writer.hpp"

#include <filesystem>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/scene_reader.hpp"

namespace fspm {
namespace {

using json = nlohmann::ordered_json;

template <int N>
json array(const Eigen::Matrix<double, N, 1>& v) {
  json a = json::array();
  for (int i = 0; i < N; ++i) a.push_back(v[i]);
  return a;
}

json sky_json(const SceneSky& sky) {
  json s = json::object();
  if (sky.source == SkySource::kBrightest) s["brightest"] = array<3>(sky.brightest);
  if (sky.source == SkySource::kSun) {
    s["sun"] = {{"elevation_deg", sky.sun_elevation_deg}, {"azimuth_deg", sky.sun_azimuth_deg}};
  }
  if (sky.source == SkySource::kNoonSun) {
    s["latitude_deg"] = sky.latitude_deg;
    s["day_of_year"] = sky.day_of_year;
  }
  if (sky.directions) s["directions"] = *sky.directions;
  if (sky.significance) s["significance"] = *sky.significance;
  if (sky.analytic) s["analytic"] = *sky.analytic;
  return s;
}

void add_surface(const ObstacleSurface& surface, json& o) {
  if (surface.translucency) o["translucency"] = *surface.translucency;
  if (surface.solid) o["solid"] = *surface.solid;
}

json shape_json(const SphereObstacle& s) {
  json o = {{"type", s.cluster ? "cluster" : "sphere"},
            {"center", array<3>(s.center)},
            {"radius", s.radius_m}};
  if (s.gamma0) o["gamma0"] = *s.gamma0;
  return o;
}
json shape_json(const BoxObstacle& b) {
  json o = {{"type", "box"}, {"center", array<3>(b.center)}, {"size", array<3>(b.size_m)}};
  if (b.axis) {
    o["axis"] = array<3>(*b.axis);
    o["angle_deg"] = b.angle_deg;
  }
  return o;
}
json shape_json(const WallObstacle& w) {
  return {{"type", "wall"},       {"from", array<2>(w.from)},   {"to", array<2>(w.to)},
          {"height", w.height_m}, {"thickness", w.thickness_m}, {"base", w.base_m}};
}
json shape_json(const MeshObstacle& m) {
  json vertices = json::array(), triangles = json::array();
  for (const auto& v : m.vertices) vertices.push_back(array<3>(v));
  for (const auto& t : m.triangles) triangles.push_back({t[0], t[1], t[2]});
  return {{"type", "mesh"}, {"vertices", vertices}, {"triangles", triangles}};
}

// Relative to the written file, so the scene and its plants can move together.
std::string relative_file(const std::string& path, const std::string& directory) {
  std::filesystem::path file = path;
  std::error_code ec;
  const auto rel = std::filesystem::relative(file, directory.empty() ? "." : directory, ec);
  if (!ec && !rel.empty()) file = rel;
  return file.generic_string();
}

json plant_json(const ScenePlant& p, const std::string& directory) {
  json o = {{"file", relative_file(p.file, directory)},
            {"position", array<3>(p.position)},
            {"rotation_deg", array<3>(p.rotation_deg)},
            {"scale", p.scale}};
  if (p.age) o["age"] = *p.age;
  if (p.length_unit) o["length_unit"] = std::string(length_unit_name(*p.length_unit));
  if (p.diameter_unit) o["diameter_unit"] = std::string(length_unit_name(*p.diameter_unit));
  return o;
}

json terrain_json(const SceneTerrain& t, const std::string& directory) {
  return {{"heightfield", relative_file(t.heightfield, directory)},
          {"metres_per_pixel", t.metres_per_pixel},
          {"height_scale_m", t.height_scale_m},
          {"stride", t.stride}};
}

json population_json(const ScenePopulation& p, const std::string& directory) {
  json o;
  if (!p.map.empty()) o["map"] = relative_file(p.map, directory);
  json classes = json::array();
  for (const auto& c : p.classes) {
    json plants = json::array();
    for (const auto& q : c.plants) {
      json j = {{"file", relative_file(q.file, directory)}, {"probability", q.probability}};
      if (q.age) j["age"] = *q.age;
      plants.push_back(j);
    }
    classes.push_back({{"value", c.value}, {"density", c.density}, {"plants", plants}});
  }
  o["classes"] = classes;
  o["min_distance_m"] = p.min_distance_m;
  if (p.count) o["count"] = *p.count;
  o["seed"] = p.seed;
  o["scale_jitter"] = p.scale_jitter;
  return o;
}

}  // namespace

json scene_description_json(const SceneDescription& scene, const std::string& directory) {
  json doc = {{"fspm_scene", kSceneVersion}};
  if (!scene.comment.empty()) doc["comment"] = scene.comment;
  doc["sky"] = sky_json(scene.sky);
  if (scene.gamma0) doc["gamma0"] = *scene.gamma0;
  if (scene.ground) {
    json g = {{"z", scene.ground->height_m}};
    add_surface(scene.ground->surface, g);
    doc["ground"] = g;
  }
  json obstacles = json::array();
  for (const auto& o : scene.obstacles) {
    json j = std::visit([](const auto& shape) { return shape_json(shape); }, o.shape);
    add_surface(o.surface, j);
    obstacles.push_back(j);
  }
  doc["obstacles"] = obstacles;
  json plants = json::array();
  for (const auto& p : scene.plants) plants.push_back(plant_json(p, directory));
  doc["plants"] = plants;
  if (scene.terrain) doc["terrain"] = terrain_json(*scene.terrain, directory);
  if (scene.population) doc["population"] = population_json(*scene.population, directory);
  return doc;
}

namespace {

// Top-level keys one a line, lists one entry a line: short enough to read, easy to diff.
std::string scene_text(const json& doc) {
  std::string text = "{";
  const char* separator = "\n";
  for (const auto& [key, value] : doc.items()) {
    text += separator + std::string("  ") + json(key).dump() + ": ";
    separator = ",\n";
    if (!value.is_array() || value.empty()) {
      text += value.dump();
      continue;
    }
    text += "[";
    for (std::size_t i = 0; i < value.size(); ++i) {
      text += (i ? ",\n    " : "\n    ") + value[i].dump(-1, ' ', false);
    }
    text += "\n  ]";
  }
  return text + "\n}\n";
}

}  // namespace

void write_scene_description(const SceneDescription& scene, const std::string& path) {
  const std::string directory = std::filesystem::path(path).parent_path().string();
  const std::string text = scene_text(scene_description_json(scene, directory));
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace fspm
