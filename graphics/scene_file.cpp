#include "graphics/scene_file.hpp"

#include <Eigen/Geometry>
#include <map>
#include <numbers>
#include <tuple>

#include "fspm/scene_reader.hpp"

namespace fspm::graphics {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

}  // namespace

Eigen::Matrix3d SceneInstance::linear() const {
  const Eigen::Matrix3d r =
      (Eigen::AngleAxisd(rotation_deg.z() * kDegToRad, Eigen::Vector3d::UnitZ()) *
       Eigen::AngleAxisd(rotation_deg.y() * kDegToRad, Eigen::Vector3d::UnitY()) *
       Eigen::AngleAxisd(rotation_deg.x() * kDegToRad, Eigen::Vector3d::UnitX()))
          .toRotationMatrix();
  return scale * r;
}

bool is_scene_path(const std::string& path) { return fspm::is_scene_path(path); }

SceneFile scene_plants(const std::vector<ScenePlant>& plants) {
  SceneFile scene;
  std::map<std::tuple<std::string, double, int, int>, std::size_t> source_index;
  const MtgTreeOptions defaults = default_mtg_tree_options();
  for (const ScenePlant& plant : plants) {
    const auto unit_key = [](const std::optional<LengthUnit>& u) {
      return u ? static_cast<int>(*u) : -1;
    };
    const auto key = std::make_tuple(plant.file, plant.age.value_or(-1.0),
                                     unit_key(plant.length_unit), unit_key(plant.diameter_unit));
    auto [it, added] = source_index.emplace(key, scene.sources.size());
    if (added) {
      MtgTreeOptions mtg = defaults;
      if (plant.length_unit) mtg.length_unit = *plant.length_unit;
      if (plant.diameter_unit) mtg.diameter_unit = *plant.diameter_unit;
      scene.sources.push_back({plant.file, plant.age.value_or(-1.0), mtg});
    }
    SceneInstance inst;
    inst.source = it->second;
    inst.position = plant.position;
    inst.rotation_deg = plant.rotation_deg;
    inst.scale = plant.scale;
    scene.instances.push_back(inst);
  }
  return scene;
}

SceneFile parse_scene(const std::string& text, const std::string& scene_path) {
  return scene_plants(parse_scene_description(text, scene_path).plants);
}

SceneFile read_scene_file(const std::string& path) {
  return scene_plants(read_scene_description(path).plants);
}

}  // namespace fspm::graphics
