// OpenImageIO comes with the VTK back end (graphics/CMakeLists.txt), loaded on first use through
// fspm/image_file.
#include "fspm/image_file.hpp"
#include "graphics/float_image.hpp"

namespace fspm::graphics {

FloatImage read_float_image(const std::string& path) {
  ImageInfo spec;
  FloatImage image;
  // Channel 0 only, converted by OpenImageIO (integers to [0, 1]).
  image.values = read_image_floats(path, 1, spec);
  image.width = spec.width;
  image.height = spec.height;
  return image;
}

}  // namespace fspm::graphics
