// OpenImageIO comes with the VTK back end (graphics/CMakeLists.txt).
#include <OpenImageIO/imageio.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/float_image.hpp"

namespace fspm::graphics {

FloatImage read_float_image(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) {
    throw IoError("cannot read image: no such file", path);
  }
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw IoError("cannot read image: " + OIIO::geterror(), path);
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1) {
    throw IoError("image has no pixels", path);
  }
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
