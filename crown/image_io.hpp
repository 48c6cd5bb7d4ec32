#pragma once
// Photographs and masks in and out through OpenImageIO (any format it reads: PNG, JPEG, TIFF,
// EXR ...). Outputs are written atomically: a failed write leaves no file.
#include <string>

#include "crown/raster.hpp"

namespace fspm::crown {

// RGB in [0, 1] (grey images are repeated to three channels, alpha is dropped).
// Throws IoError when the file cannot be read.
Raster read_rgb(const std::string& path);

// Every channel as it is stored (8-bit images in [0, 1], floats of .exr and .tif unclamped).
// Throws IoError when the file cannot be read.
Raster read_raster(const std::string& path);

// A crown mask: pixels whose first channel is above half its range are crown.
// Throws IoError when unreadable, ValueError when it has no crown pixel.
Mask read_mask(const std::string& path);

// 1 or 3 channels: 8-bit in [0, 1] (clamped), or floats as they are for .exr and .tif. Throws
// ValueError for an unknown format, IoError when the file cannot be written.
void write_raster(const Raster& image, const std::string& path);
void write_mask(const Mask& mask, const std::string& path);

// Throws like write_raster would for `path`, before any work is done.
void check_image_output(const std::string& path);

}  // namespace fspm::crown
