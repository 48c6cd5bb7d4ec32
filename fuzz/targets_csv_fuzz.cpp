// libFuzzer target: the GreenLab calibration targets (`fspm greenlab fit --targets`) must either
// parse into targets with finite values or throw an fspm::Error.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fspm/error.hpp"
#include "greenlab/calibration.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (const fspm::greenlab::Target& t : fspm::greenlab::parse_targets_csv(text, "fuzz.csv")) {
      if (!std::isfinite(t.value)) std::abort();
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
