// libFuzzer target: a growth-parameter file (fspm grow) must either parse into parameters that
// pass validation or throw an fspm::Error naming the problem.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "environment/growth_params.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::environment::GrowthParams p = fspm::environment::parse_growth_params(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    p.validate();
  } catch (const fspm::Error&) {
  }
  return 0;
}
