#pragma once
// The first channel of an image as floats, for maps read as numbers: heightfields and class
// maps. Row 0 is at the top.
#include <cstddef>
#include <string>
#include <vector>

namespace fspm::graphics {

struct FloatImage {
  int width = 0;
  int height = 0;
  // width * height, row-major from the top: in [0, 1] for integer images (8-bit 255 is 1, 16-bit
  // 65535 is 1), as stored for floating-point images (OpenEXR, float TIFF).
  std::vector<float> values;

  float at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
};

// Reads the first channel of the first subimage through OpenImageIO. Throws IoError when the file
// is missing or cannot be decoded, ValueError when fspm was built without OpenImageIO
// (FSPM_WITH_VTK=OFF).
FloatImage read_float_image(const std::string& path);

}  // namespace fspm::graphics
