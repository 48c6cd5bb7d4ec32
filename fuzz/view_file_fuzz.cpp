// libFuzzer target: the cpfg view-file reader must either return settings or throw fspm::Error.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "lsystem/turtle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)fspm::lsystem::parse_view(std::string_view(reinterpret_cast<const char*>(data), size),
                                    "fuzz");
  } catch (const fspm::Error&) {
  }
  return 0;
}
