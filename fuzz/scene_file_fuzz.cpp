// libFuzzer target: a scene file or points file must either parse or throw an fspm::Error naming
// the problem; a parsed scene must give light in [0, 1].
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "environment/light_model.hpp"
#include "environment/points_file.hpp"
#include "environment/scene_file.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    fspm::environment::Scene scene = fspm::environment::parse_scene_json(text, "fuzz.json");
    if (scene.sky.directions > 4096) scene.sky.directions = 4096;
    if (scene.spheres.size() + scene.boxes.size() + scene.meshes.size() < 64) {
      const fspm::environment::LightModel model(scene);
      const double light = model.evaluate(Eigen::Vector3d(0.1, 0.2, 0.3)).light;
      if (!(light >= 0.0 && light <= 1.0)) __builtin_trap();
    }
  } catch (const fspm::Error&) {
  }
  try {
    fspm::environment::parse_points_csv(text, "fuzz.csv");
  } catch (const fspm::Error&) {
  }
  return 0;
}
