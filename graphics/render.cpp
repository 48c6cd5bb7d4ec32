#include "graphics/render.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::graphics {

void parse_size(std::string_view text, int& width, int& height) {
  const std::optional<ImageSize> size = find_image_size(text);
  if (!size) {
    throw ValueError("bad image size '" + std::string(text) +
                     "' (expected WIDTHxHEIGHT, e.g. 1024x768, each 1.." +
                     std::to_string(kMaxImageSide) + ")");
  }
  width = size->width;
  height = size->height;
}

void RenderOptions::validate() const {
  if (width < 1 || height < 1 || width > 16384 || height > 16384) {
    throw ValueError("render: width and height must be 1..16384 pixels");
  }
  // VTK's render window, its buffers and read-back and the image returned: a render of n pixels
  // peaks about 40 n bytes above the program (measured at 2048, 4096 and 8192 squared; 8192 x
  // 8192 took 2.8 GB under a 256 MiB limit, refused nowhere).
  constexpr double kBytesPerPixel = 40.0;
  check_memory(kBytesPerPixel * static_cast<double>(width) * static_cast<double>(height),
               "a render of " + size_text(width, height));
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

double scale_bar_length(double height_m) {
  if (!(height_m > 0.0) || !std::isfinite(height_m)) return 0.0;
  const double target = height_m / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(target)));
  // A little slack: a fifth of 10 m is 2 m, and 2 m is meant even when the division rounds down.
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * decade <= target * (1.0 + 1e-9)) return step * decade;
  }
  return decade;
}

double ortho_height_to_fit(View view, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
                           double aspect) {
  const Eigen::Vector3d size = (hi - lo).cast<double>().cwiseMax(0.0);
  double up = size.z(), across = size.x();
  switch (view) {
    case View::kFront:  // looking along +y: x across, z up
      break;
    case View::kSide:  // along -x: y across
      across = size.y();
      break;
    case View::kTop:  // down -z, y up
      up = size.y();
      break;
    case View::kIso:  // any direction: the diagonal bounds every projection
      up = across = size.norm();
      break;
  }
  return std::max(up, across / aspect);
}

}  // namespace fspm::graphics
