// libFuzzer target: a sky file (`fspm adapt --sky`, `fspm tree info --sky`) must either give a
// site sky whose mean light direction is a unit vector above the horizon, or throw an fspm::Error.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "environment/site_sky.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::environment::SiteSky sky = fspm::environment::parse_site_sky_text(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    const Eigen::Vector3d b = fspm::environment::mean_light_direction(sky);
    if (!(std::abs(b.norm() - 1.0) < 1e-9) || !(b.z() > 0.0)) std::abort();
  } catch (const fspm::Error&) {
  }
  return 0;
}
