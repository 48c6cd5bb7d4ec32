// libFuzzer target: a GreenLab plant description must either parse into a valid description or
// throw an fspm::Error naming the problem.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "greenlab/plant_params.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::greenlab::PlantParams p = fspm::greenlab::parse_plant_params(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    p.validate();
  } catch (const fspm::Error&) {
  }
  return 0;
}
