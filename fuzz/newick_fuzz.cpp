// libFuzzer target: the Newick reader must either parse or throw fspm::ParseError.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "fspm/newick_format.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::TreeGraph t =
        fspm::parse_newick(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    (void)fspm::to_newick(t);
  } catch (const fspm::Error&) {
  }
  return 0;
}
