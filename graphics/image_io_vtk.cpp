// Images through OpenImageIO (built with the VTK option, which brings OpenImageIO along), loaded
// on first use (fspm/image_codec.hpp). Encoded in memory, then written atomically like every fspm
// output.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"
#include "fspm/image_codec.hpp"
#include "graphics/image.hpp"

namespace fspm::graphics {

void check_image_path(const std::string& path) {
  if (image_writer_format(path).empty()) {
    throw ValueError("unknown image format for '" + path +
                         "' (expected an extension such as .png, .tif or .exr)",
                     path);
  }
  const std::filesystem::path dir = std::filesystem::path(path).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir)) {
    throw IoError("cannot write: directory '" + dir.string() + "' does not exist", path);
  }
}

void write_image(const Image& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * image.height * 4) {
    throw ValueError("image has no pixels or a wrong buffer size", path);
  }
  const std::string format = image_writer_format(path);
  if (format.empty()) {
    throw ValueError("unknown image format for '" + path +
                         "' (expected an extension such as .png, .tif or .exr)",
                     path);
  }
  // PNG and JPEG carry no alpha we need: RGB keeps files small; TIFF/EXR keep RGBA.
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
  // Encoded in memory: nothing touches disk yet.
  const std::vector<unsigned char> bytes = encode_image(
      path, ImageInfo{image.width, image.height, channels, 1}, PixelType::kUint8, data);
  write_file_atomically(
      path,
      [&](std::ostream& stream) {
        stream.write(reinterpret_cast<const char*>(bytes.data()),
                     static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

Image read_image(const std::string& path) {
  check_image_file(path);
  const ImageInfo spec = read_image_info(path);
  // The stored channels as bytes, the decoder's own buffer of them, and the RGBA copy.
  check_image_size(
      path, spec.width, spec.height, std::max(spec.channels, 1),
      1.0 + static_cast<double>(spec.bytes_per_value) + 4.0 / std::max(spec.channels, 1));
  Image image;
  image.width = spec.width;
  image.height = spec.height;
  std::vector<std::uint8_t> raw(static_cast<std::size_t>(spec.width) * spec.height * spec.channels);
  read_image_pixels(path, spec.channels, PixelType::kUint8, raw.data());
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
