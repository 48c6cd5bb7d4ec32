#include "fspm/error.hpp"
#include "graphics/float_image.hpp"

namespace fspm::graphics {

FloatImage read_float_image(const std::string& path) {
  throw ValueError("reading images needs OpenImageIO (build with FSPM_WITH_VTK=ON)", path);
}

}  // namespace fspm::graphics
