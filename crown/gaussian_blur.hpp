#pragma once
// Separable Gaussian blur of a one-channel raster restricted to a mask (normalized convolution:
// pixels outside the mask neither contribute nor get a value), so the sky around a crown does not
// bleed into its border.
#include "crown/raster.hpp"

namespace fspm::crown {

// sigma in pixels (> 0); the kernel is cut at 3 sigma. Pixels outside `mask` are 0 on output.
Raster masked_gaussian_blur(const Raster& image, const Mask& mask, double sigma);

}  // namespace fspm::crown
