// libFuzzer target: the mesh readers (OBJ with groups, PLY faces) must either read or throw an
// fspm::Error. The first byte chooses the reader, the rest is the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "scans/obj_reader.hpp"
#include "scans/ply_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view file(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] % 2 == 0) {
      (void)fspm::scans::parse_obj_mesh(file, "fuzz.obj");
    } else {
      (void)fspm::scans::parse_ply_mesh(file, "fuzz.ply");
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
