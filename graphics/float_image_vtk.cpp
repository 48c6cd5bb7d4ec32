// OpenImageIO comes with the VTK back end (graphics/CMakeLists.txt), loaded on first use
// (fspm/image_codec.hpp).
#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"
#include "fspm/image_codec.hpp"
#include "graphics/float_image.hpp"

namespace fspm::graphics {

FloatImage read_float_image(const std::string& path) {
  check_image_file(path);
  const ImageInfo spec = read_image_info(path);
  // Channel 0 as floats, and the decoder's own buffer of every stored channel.
  check_image_size(path, spec.width, spec.height, 1,
                   sizeof(float) + static_cast<double>(spec.channels) *
                                       static_cast<double>(spec.bytes_per_value));
  FloatImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.values.resize(static_cast<std::size_t>(spec.width) * spec.height);
  // Channel 0 only, converted by OpenImageIO (integers to [0, 1]).
  read_image_pixels(path, 1, PixelType::kFloat, image.values.data());
  return image;
}

}  // namespace fspm::graphics
