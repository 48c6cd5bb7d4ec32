// Images through OpenImageIO (built with the VTK option, which brings OpenImageIO along), loaded
// on first use; the checks, the encoding in memory and the atomic write are fspm/image_file's.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/image_file.hpp"
#include "graphics/image.hpp"

namespace fspm::graphics {

void check_image_path(const std::string& path) { check_image_output(path); }

void write_image(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw ValueError("image has no pixels or a wrong buffer size", path);
  }
  check_image_output(path);
  // PNG and JPEG carry no alpha we need: RGB keeps files small; TIFF/EXR keep RGBA.
  const std::string format = image_writer_format(path);
  const int channels = (format == "png" || format == "jpeg") ? 3 : 4;
  std::vector<std::uint8_t> pixels;
  const std::uint8_t* data = image.rgba.data();
  if (channels == 3) {
    pixels.resize(static_cast<std::size_t>(image.width) * image.height * 3);
    for (std::size_t i = 0, n = pixels.size() / 3; i < n; ++i) {
      for (int c = 0; c < 3; ++c) pixels[3 * i + c] = image.rgba[4 * i + c];
    }
    data = pixels.data();
  }
  write_image_file(path, ImageInfo{image.width, image.height, channels, 1}, PixelType::kUint8,
                   data);
}

Image read_image(const std::string& path) {
  ImageInfo spec;
  // The stored channels as bytes, and beside them the RGBA copy (4 bytes per pixel).
  const std::vector<std::uint8_t> raw = read_image_bytes(path, 0, spec, 4.0);
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgba.assign(static_cast<std::size_t>(spec.width) * spec.height * 4, 255);
  for (std::size_t i = 0, n = static_cast<std::size_t>(spec.width) * spec.height; i < n; ++i) {
    for (int c = 0; c < std::min(spec.channels, 4); ++c) {
      image.rgba[4 * i + c] = raw[i * spec.channels + c];
    }
    if (spec.channels < 3) {
      image.rgba[4 * i + 1] = image.rgba[4 * i + 2] = image.rgba[4 * i];
    }
  }
  return image;
}

}  // namespace fspm::graphics
