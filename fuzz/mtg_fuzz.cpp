// libFuzzer target: the MTG reader must either parse or throw an fspm::Error, and what it parses
// must export again.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string_view>

#include "fspm/error.hpp"
#include "fspm/mtg_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::TreeGraph t =
        fspm::parse_mtg(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    std::ostringstream out;
    fspm::write_mtg(t, out);
  } catch (const fspm::Error&) {
  }
  return 0;
}
