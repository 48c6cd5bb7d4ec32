#pragma once
// An 8-bit RGBA raster (row 0 at the top) and writing it through OpenImageIO.
#include <cstdint>
#include <string>
#include <vector>

namespace fspm::graphics {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, row 0 at the top

  std::uint8_t* pixel(int x, int y) {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
};

// Format from the extension (.png, .tif/.tiff, .exr, .jpg ...: whatever OpenImageIO writes),
// written atomically. Throws ValueError for an unknown format, IoError when it cannot be written,
// ValueError when fspm was built without OpenImageIO (FSPM_WITH_VTK=OFF).
void write_image(const Image& image, const std::string& path);

// Checks, before any rendering, that `path` names a format OpenImageIO writes and an existing
// directory. Throws ValueError / IoError like write_image would.
void check_image_path(const std::string& path);

// Reads an image back as 8-bit RGBA (for tests and comparisons). Throws IoError.
Image read_image(const std::string& path);

}  // namespace fspm::graphics
