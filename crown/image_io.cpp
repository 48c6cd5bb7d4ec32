// Through fspm/image_file (OpenImageIO loaded on first use, the size checks before decoding,
// encoded in memory, then written atomically).
#include "crown/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fspm/error.hpp"
#include "fspm/image_file.hpp"

namespace fspm::crown {

Raster read_rgb(const std::string& path) {
  ImageInfo spec;
  const std::vector<float> pixels = read_image_floats(path, 0, spec);
  Raster out(spec.width, spec.height, 3);
  const int n = spec.channels;
  for (std::size_t i = 0, count = out.values.size() / 3; i < count; ++i) {
    for (int c = 0; c < 3; ++c) {
      out.values[3 * i + c] = std::clamp(pixels[i * n + (n >= 3 ? c : 0)], 0.0f, 1.0f);
    }
  }
  return out;
}

Raster read_raster(const std::string& path) {
  ImageInfo spec;
  Raster out;
  out.values = read_image_floats(path, 0, spec);
  out.width = spec.width;
  out.height = spec.height;
  out.channels = spec.channels;
  return out;
}

Mask read_mask(const std::string& path) {
  ImageInfo spec;
  const std::vector<float> pixels = read_image_floats(path, 0, spec);
  Mask mask(spec.width, spec.height);
  for (std::size_t i = 0; i < mask.inside.size(); ++i) {
    mask.inside[i] = pixels[i * spec.channels] > 0.5f ? 1 : 0;
  }
  if (mask.count() == 0) {
    throw ValueError("the mask has no crown pixel (expected white crown on black)", path);
  }
  return mask;
}

void check_image_output(const std::string& path) { fspm::check_image_output(path); }

void write_raster(const Raster& image, const std::string& path) {
  check_image_output(path);
  if (image.width < 1 || image.height < 1 || (image.channels != 1 && image.channels != 3)) {
    throw ValueError("image to write has no pixels or not 1 or 3 channels", path);
  }
  // Formats that hold floats (OpenEXR, TIFF) get the values as they are: radii in metres.
  const std::string format = image_writer_format(path);
  const bool floats = format == "openexr" || format == "tiff";
  std::vector<std::uint8_t> bytes(floats ? 0 : image.values.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    bytes[i] =
        static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(image.values[i], 0.0f, 1.0f)));
  }
  const PixelType type = floats ? PixelType::kFloat : PixelType::kUint8;
  const void* data = floats ? static_cast<const void*>(image.values.data()) : bytes.data();
  write_image_file(path, ImageInfo{image.width, image.height, image.channels, floats ? 4 : 1}, type,
                   data);
}

void write_mask(const Mask& mask, const std::string& path) {
  Raster image(mask.width, mask.height, 1);
  for (std::size_t i = 0; i < mask.inside.size(); ++i)
    image.values[i] = mask.inside[i] ? 1.0f : 0.0f;
  write_raster(image, path);
}

}  // namespace fspm::crown
