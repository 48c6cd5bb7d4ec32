#pragma once
// The resolution the reconstruction works at. The inflation (Argudo 4.3.2) is a thin-plate
// surface that varies over the crown's width, the relief pyramid's coarsest level (sigma 8
// pixels) and the cubemap (0.7 of the crown's width, at most 256 texels) need a crown a few
// hundred pixels wide; Argudo works with 256-texel cubemaps. A phone photograph's crown is
// 2 000-3 000 pixels wide: solving the 13-point system for its millions of pixels costs
// gigabytes and minutes and adds nothing the crown can show. The photograph and its mask are
// therefore reduced by a whole factor until the crown's bounding box is at most `max_side` pixels
// on its longer side, by block means. The mask's border keeps the full resolution's accuracy
// through the coverage of each block (the share of its pixels inside the crown): the silhouette
// vertices are placed where the full-resolution border passes (crown/silhouette.hpp).
#include "crown/raster.hpp"

namespace fspm::crown {

struct WorkingImages {
  Raster photo;     // RGB: each block's mean over its foliage pixels when it has some, else all
  Mask mask;        // blocks at least half inside the crown
  Raster coverage;  // share of each block inside the crown; empty at factor 1 (the mask itself)
  Mask foliage;     // blocks holding at least one foliage pixel
  int factor = 1;   // photograph pixels per working pixel along each side
};

// The smallest factor that brings the crown's bounding box within `max_side` pixels. Throws
// ValueError for an empty mask or max_side < 16.
int working_factor(const Mask& mask, int max_side);

// `foliage` (may be null: every pixel is foliage) marks the pixels that hold crown texture
// (crown/gap_fill.hpp); blocks without any are the gaps left to fill at the working resolution.
WorkingImages working_images(const Raster& photo, const Mask& mask, const Mask* foliage,
                             int max_side);

}  // namespace fspm::crown
