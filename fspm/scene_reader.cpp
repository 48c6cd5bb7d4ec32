#include "fspm/scene_reader.hpp"

#include <filesystem>
#include <set>
#include <system_error>

#include "fspm/file_kind.hpp"
#include "fspm/input_file.hpp"
#include "fspm/json_fields.hpp"
#include "fspm/scene_landscape_reader.hpp"
#include "fspm/scene_obstacle_reader.hpp"

namespace fspm {
namespace {

using nlohmann::json;

SceneSky read_sky(const JsonFields& f, const json& s, const std::string& path) {
  if (!s.is_object()) f.fail(path, "an object", &s);
  f.check_keys(s, path,
               {"model", "brightest", "sun", "latitude_deg", "day_of_year", "directions",
                "significance", "analytic"});
  SceneSky sky;
  if (s.contains("model") && s.at("model") != "cos2")
    f.fail(path + "/model", "\"cos2\"", &s.at("model"));
  if (s.contains("brightest") + s.contains("sun") + s.contains("latitude_deg") > 1) {
    f.fail(path, "only one of brightest, sun, latitude_deg");
  }
  if (s.contains("brightest")) {
    sky.source = SkySource::kBrightest;
    sky.brightest = f.vec<3>(s, path, "brightest");
    if (sky.brightest.norm() <= 0.0) {
      f.fail(path + "/brightest", "a non-zero vector", &s.at("brightest"));
    }
  } else if (s.contains("sun")) {
    const json& sun = s.at("sun");
    const std::string p = path + "/sun";
    if (!sun.is_object()) f.fail(p, "an object with elevation_deg and azimuth_deg", &sun);
    f.check_keys(sun, p, {"elevation_deg", "azimuth_deg"});
    sky.source = SkySource::kSun;
    sky.sun_elevation_deg =
        f.number(sun, p, "elevation_deg", -90, 90, "an elevation in [-90, 90] degrees");
    sky.sun_azimuth_deg =
        f.number(sun, p, "azimuth_deg", -360, 360, "an azimuth in [-360, 360] degrees");
  } else if (s.contains("latitude_deg")) {
    sky.source = SkySource::kNoonSun;
    sky.latitude_deg = f.number(s, path, "latitude_deg", -90, 90, "a latitude in [-90, 90]");
    sky.day_of_year = f.number(s, path, "day_of_year", 1, 366, "a day of year in [1, 366]");
  } else if (s.contains("day_of_year")) {
    f.fail(path + "/latitude_deg", "a latitude to go with day_of_year (missing)");
  }
  if (const auto d = f.optional_number(s, path, "directions", 1, kMaxSkyDirections,
                                       "a direction count in [1, 1048576]")) {
    sky.directions = static_cast<int>(*d);
  }
  sky.significance = f.optional_number(s, path, "significance", 0, 0.999, "a number in [0, 1)");
  sky.analytic = f.optional_boolean(s, path, "analytic");
  return sky;
}

// A crown reconstructed from a photograph (`fspm crown`, Argudo ch. 4-5): its mesh (.glb or
// .obj), or the output directory holding crown.glb; checked here so that a wrong path is named
// with its line in the scene file.
std::string crown_mesh_path(const JsonFields& f, const json& p, const std::string& path,
                            const std::filesystem::path& base) {
  const char* what = "a crown from fspm crown: its .glb or .obj mesh, or its output directory";
  std::filesystem::path file = f.text(p, path, "crown", what);
  if (file.is_relative() && !base.empty()) file = base / file;
  file = file.lexically_normal();
  std::error_code ec;
  const auto fail = [&](const std::string& why) {
    f.fail(path + "/crown", std::string(what) + " ('" + file.string() + "' " + why + ")",
           &p.at("crown"));
  };
  if (!std::filesystem::exists(file, ec)) fail("does not exist");
  if (std::filesystem::is_directory(file, ec)) {
    file /= kCrownMeshName;
    if (!std::filesystem::is_regular_file(file, ec)) fail("does not exist");
  }
  if (!is_grouped_mesh_kind(file_kind_by_extension(file.string()))) {
    fail("is neither a .glb, .gltf or .obj mesh nor a directory");
  }
  return file.string();
}

ScenePlant read_plant(const JsonFields& f, const json& p, const std::string& path,
                      const std::filesystem::path& base) {
  if (!p.is_object())
    f.fail(path, "a plant object with file or crown, position, rotation_deg, scale, age", &p);
  f.check_keys(p, path,
               {"file", "crown", "position", "rotation_deg", "scale", "age", "length_unit",
                "diameter_unit"});
  ScenePlant plant;
  if (p.contains("crown")) {
    if (p.contains("file")) f.fail(path, "either file or crown, not both", &p);
    plant.file = crown_mesh_path(f, p, path, base);
  } else {
    std::filesystem::path file =
        f.text(p, path, "file", "a plant file (tree, .ctree or plant .toml)");
    if (file.is_relative() && !base.empty()) file = base / file;
    plant.file = file.lexically_normal().string();
  }
  if (p.contains("position")) plant.position = f.vec<3>(p, path, "position");
  if (p.contains("rotation_deg")) {
    // A single number is a rotation about z.
    plant.rotation_deg = p.at("rotation_deg").is_array()
                             ? f.vec<3>(p, path, "rotation_deg")
                             : Eigen::Vector3d(0, 0,
                                               f.number(p, path, "rotation_deg", -1e9, 1e9,
                                                        "degrees, or [x, y, z] degrees"));
  }
  plant.scale = f.optional_number(p, path, "scale", 1e-9, 1e9, "a scale > 0").value_or(1.0);
  plant.age = f.optional_number(p, path, "age", 0, 1e9, "an age >= 0");
  for (const auto& [key, unit] : {std::pair{"length_unit", &plant.length_unit},
                                  std::pair{"diameter_unit", &plant.diameter_unit}}) {
    if (p.contains(key)) {
      *unit = length_unit_from_name(f.text(p, path, key, "m, dm, cm or mm"), path + "/" + key);
    }
  }
  return plant;
}

// One of the current key `now` or the earlier `old` (not both); nullptr when neither.
const json* list_of(const JsonFields& f, const json& doc, const char* now, const char* old,
                    const std::string& what) {
  if (doc.contains(now) && doc.contains(old)) {
    f.fail(std::string("/") + old, std::string("only one of ") + now + " and " + old);
  }
  const char* key = doc.contains(now) ? now : doc.contains(old) ? old : nullptr;
  if (!key) return nullptr;
  if (!doc.at(key).is_array()) f.fail(std::string("/") + key, what, &doc.at(key));
  return &doc.at(key);
}

void check_top_keys(const JsonFields& f, const json& doc) {
  static const std::set<std::string> earlier = {"occluders", "instances"};
  for (auto it = doc.begin(); it != doc.end(); ++it) {
    if (earlier.count(it.key())) continue;
    f.check_keys(json{{it.key(), nullptr}}, "",
                 {"fspm_scene", "comment", "sky", "gamma0", "ground", "obstacles", "plants",
                  "terrain", "population"});
  }
  if (doc.contains("fspm_scene") && doc.at("fspm_scene") != 1 &&
      doc.at("fspm_scene") != kSceneVersion) {
    f.fail("/fspm_scene", "a scene version 1 or 2", &doc.at("fspm_scene"));
  }
}

// The terrain and the population spread over it (a population needs the terrain).
void read_landscape(const JsonFields& f, const json& doc, const std::filesystem::path& base,
                    SceneDescription& scene) {
  if (doc.contains("terrain")) {
    scene.terrain = read_scene_terrain(f, doc.at("terrain"), "/terrain", base);
  }
  if (doc.contains("population")) {
    if (!scene.terrain) f.fail("/terrain", "a terrain to place the population on (missing)");
    scene.population = read_scene_population(f, doc.at("population"), "/population", base);
  }
}

}  // namespace

SceneDescription parse_scene_description(std::string_view text, const std::string& file_name) {
  const json doc = parse_json_text(text, file_name);
  const JsonFields f(text, file_name);
  if (!doc.is_object()) f.fail("", "a JSON object with sky, ground, obstacles and plants", &doc);
  check_top_keys(f, doc);
  SceneDescription scene;
  if (doc.contains("comment")) scene.comment = f.text(doc, "", "comment", "a non-empty text");
  if (doc.contains("sky")) scene.sky = read_sky(f, doc.at("sky"), "/sky");
  scene.gamma0 =
      f.optional_number(doc, "", "gamma0", 0.0, 1.0, "a base cluster translucency in [0, 1]");
  if (doc.contains("ground")) {
    f.check_keys(doc.at("ground"), "/ground", {"z", "translucency", "solid"});
    scene.ground = read_scene_ground(f, doc.at("ground"), "/ground");
  }
  if (const json* list = list_of(f, doc, "obstacles", "occluders", "an array of obstacles")) {
    const bool earlier = doc.contains("occluders");
    const std::string key = earlier ? "/occluders/" : "/obstacles/";
    for (std::size_t i = 0; i < list->size(); ++i) {
      read_scene_obstacle(f, (*list)[i], key + std::to_string(i), earlier, scene);
    }
  }
  const std::filesystem::path base = std::filesystem::path(file_name).parent_path();
  if (const json* list = list_of(f, doc, "plants", "instances", "an array of plants")) {
    const std::string key = doc.contains("plants") ? "/plants/" : "/instances/";
    for (std::size_t i = 0; i < list->size(); ++i) {
      scene.plants.push_back(read_plant(f, (*list)[i], key + std::to_string(i), base));
    }
  }
  read_landscape(f, doc, base, scene);
  return scene;
}

SceneDescription read_scene_description(const std::string& path) {
  return parse_scene_description(read_text_input_file(path), path);
}

bool is_scene_path(const std::string& path) {
  return file_kind_by_extension(path) == FileKind::kScene;
}

}  // namespace fspm
