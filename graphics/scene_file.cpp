#include "graphics/scene_file.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/nesting_depth.hpp"

namespace fspm::graphics {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

double number(const nlohmann::json& v, const std::string& what, const std::string& file) {
  if (!v.is_number()) throw ParseError(what + " must be a number", file);
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw ParseError(what + " must be finite", file);
  return x;
}

Eigen::Vector3d vector3(const nlohmann::json& v, const std::string& what, const std::string& file) {
  if (!v.is_array() || v.size() != 3) throw ParseError(what + " must be [x, y, z]", file);
  return {number(v[0], what, file), number(v[1], what, file), number(v[2], what, file)};
}

}  // namespace

Eigen::Matrix3d SceneInstance::linear() const {
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(rotation_deg.z() * kDegToRad, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(rotation_deg.y() * kDegToRad, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(rotation_deg.x() * kDegToRad, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return scale * r;
}

bool is_scene_path(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".json";
}

SceneFile parse_scene(const std::string& text, const std::string& scene_path) {
  check_json_depth(text, scene_path);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // Line and column of the byte the parser stopped at.
    int line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw ParseError("scene is not valid JSON", scene_path, line, column);
  }
  if (!doc.is_object()) throw ParseError("scene must be a JSON object", scene_path);
  for (const auto& [key, value] : doc.items()) {
    if (key != "fspm_scene" && key != "instances" && key != "comment") {
      throw ParseError("unknown scene key '" + key + "' (expected fspm_scene, instances)",
                       scene_path);
    }
  }
  if (doc.contains("fspm_scene") && doc["fspm_scene"] != 1) {
    throw ParseError("unsupported scene version (expected \"fspm_scene\": 1)", scene_path);
  }
  if (!doc.contains("instances") || !doc["instances"].is_array()) {
    throw ParseError("scene needs an \"instances\" array", scene_path);
  }
  const std::filesystem::path base = std::filesystem::path(scene_path).parent_path();
  SceneFile scene;
  std::map<std::pair<std::string, double>, std::size_t> source_index;
  std::size_t index = 0;
  for (const auto& item : doc["instances"]) {
    const std::string where = "instance " + std::to_string(index++) + ": ";
    if (!item.is_object()) throw ParseError(where + "must be an object", scene_path);
    for (const auto& [key, value] : item.items()) {
      if (key != "file" && key != "position" && key != "rotation_deg" && key != "scale" &&
          key != "age") {
        throw ParseError(
            where + "unknown key '" + key + "' (expected file, position, rotation_deg, scale, age)",
            scene_path);
      }
    }
    if (!item.contains("file") || !item["file"].is_string() ||
        item["file"].get<std::string>().empty()) {
      throw ParseError(where + "needs a \"file\" (tree, .ctree or plant .toml)", scene_path);
    }
    std::filesystem::path file = item["file"].get<std::string>();
    if (file.is_relative() && !base.empty()) file = base / file;
    SceneInstance inst;
    if (item.contains("position"))
      inst.position = vector3(item["position"], where + "position", scene_path);
    if (item.contains("rotation_deg")) {
      const auto& r = item["rotation_deg"];
      inst.rotation_deg =
          r.is_array() ? vector3(r, where + "rotation_deg", scene_path)
                       : Eigen::Vector3d(0, 0, number(r, where + "rotation_deg", scene_path));
    }
    if (item.contains("scale")) {
      inst.scale = number(item["scale"], where + "scale", scene_path);
      if (!(inst.scale > 0.0)) throw ParseError(where + "scale must be > 0", scene_path);
    }
    double age = -1.0;
    if (item.contains("age")) {
      age = number(item["age"], where + "age", scene_path);
      if (age < 0.0) throw ParseError(where + "age must be >= 0", scene_path);
    }
    const auto key = std::make_pair(file.lexically_normal().string(), age);
    auto [it, added] = source_index.emplace(key, scene.sources.size());
    if (added) scene.sources.push_back({key.first, age});
    inst.source = it->second;
    scene.instances.push_back(inst);
  }
  return scene;
}

SceneFile read_scene_file(const std::string& path) {
  return parse_scene(read_input_file(path), path);
}

}  // namespace fspm::graphics
