// libFuzzer target: the .clusters reader (cluster-based tree models) must either read or throw
// an fspm::Error.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "scans/clusters_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)fspm::scans::parse_clusters_bytes(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.clusters");
  } catch (const fspm::Error&) {
  }
  return 0;
}
