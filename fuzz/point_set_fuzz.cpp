// libFuzzer target: the point-set readers (PLY ASCII and binary, PCD, XYZ/CSV, LAS) must either
// read or throw an fspm::Error. The first byte chooses the reader ('L': LAS, else its value
// modulo 3), the rest is the file.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "scans/las_reader.hpp"
#include "scans/pcd_reader.hpp"
#include "scans/ply_reader.hpp"
#include "scans/xyz_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view file(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (data[0] == 'L') {
      (void)fspm::scans::parse_las_points(file, "fuzz.las");
      return 0;
    }
    switch (data[0] % 3) {
      case 0:
        (void)fspm::scans::parse_ply_points(file, "fuzz.ply");
        break;
      case 1:
        (void)fspm::scans::parse_pcd_points(file, "fuzz.pcd");
        break;
      default:
        (void)fspm::scans::parse_xyz_points(file, "fuzz.xyz");
        break;
    }
  } catch (const fspm::Error&) {
  }
  return 0;
}
