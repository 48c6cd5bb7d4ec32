// OpenImageIO comes with the VTK back end (graphics/CMakeLists.txt).
#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/image_budget.hpp"
#include "graphics/float_image.hpp"

namespace fspm::graphics {

FloatImage read_float_image(const std::string& path) {
  check_image_file(path);
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw IoError("cannot read image: " + OIIO::geterror(), path);
  const OIIO::ImageSpec& spec = in->spec();
  // Channel 0 as floats, and the decoder's own buffer of every stored channel.
  check_image_size(path, spec.width, spec.height, 1,
                   sizeof(float) + static_cast<double>(spec.nchannels) *
                                       static_cast<double>(spec.format.size()));
  FloatImage image;
  image.width = spec.width;
  image.height = spec.height;
  image.values.resize(static_cast<std::size_t>(spec.width) * spec.height);
  // Channel 0 only, converted by OpenImageIO (integers to [0, 1]).
  if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, image.values.data())) {
    throw IoError("cannot decode image: " + in->geterror(), path);
  }
  return image;
}

}  // namespace fspm::graphics
