#include <cmath>
#include <string>

#include "fspm/error.hpp"
#include "graphics/viewer.hpp"

namespace fspm::graphics {

void ViewerOptions::validate() const {
  if (width < 1 || height < 1) {
    throw ValueError("viewer: width and height must be >= 1 pixel, got " + std::to_string(width) +
                     " x " + std::to_string(height));
  }
  if (frames < 1) throw ValueError("viewer: frames must be >= 1, got " + std::to_string(frames));
  if (close_after_frames < 0) throw ValueError("viewer: close_after_frames must be >= 0");
  if (shadow_cascades < 0 || shadow_cascades > kMaxShadowCascades) {
    throw ValueError("viewer: shadow_cascades expected 0 to " + std::to_string(kMaxShadowCascades) +
                     ", got " + std::to_string(shadow_cascades));
  }
  if (camera_distance_m < 0.0 || !std::isfinite(camera_distance_m)) {
    throw ValueError("viewer: camera_distance_m expected a finite distance >= 0 m");
  }
}

}  // namespace fspm::graphics
