// libFuzzer target: the .ctree reader must either read a valid compressed graph or throw an
// fspm::Error; what it reads must count its metamers without overflow or crash.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/error.hpp"
#include "greenlab/expand.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const fspm::CompressedTreeGraph g =
        fspm::decode_ctree(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
    (void)fspm::greenlab::metamers_at_age(g, g.final_age);
  } catch (const fspm::Error&) {
  }
  return 0;
}
