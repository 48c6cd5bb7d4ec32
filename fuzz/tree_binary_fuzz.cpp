// libFuzzer target: the .treeb binary reader must either read or throw an fspm::Error.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "fspm/binary_tree_format.hpp"
#include "fspm/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    (void)fspm::read_tree_binary(in, "fuzz");
  } catch (const fspm::Error&) {
  }
  return 0;
}
