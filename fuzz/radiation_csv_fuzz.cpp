// libFuzzer target: the hourly global radiation CSV (`fspm light --global-csv`) must either give
// 24 finite, non-negative hourly values or throw an fspm::Error.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "environment/radiation_file.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto hours = fspm::environment::parse_hourly_global_csv(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    if (hours.size() != 24) std::abort();
    for (const double w : hours) {
      if (!std::isfinite(w) || w < 0.0) std::abort();
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
