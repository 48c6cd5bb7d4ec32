// libFuzzer target: the points reader of `fspm light` must either return finite points or throw
// fspm::Error.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "environment/points_file.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto points = fspm::environment::parse_points_csv(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    for (const auto& p : points) {
      if (!p.allFinite()) std::abort();  // the reader refuses NaN and infinite coordinates
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
