#pragma once
// Binary morphology on crown masks with a square structuring element, and the connected-piece
// helpers the automatic mask needs.
#include "crown/raster.hpp"

namespace fspm::crown {

Mask dilate(const Mask& mask, int radius);
Mask erode(const Mask& mask, int radius);
// Background pixels not connected (4-neighbours) to the raster border become crown.
Mask fill_holes(const Mask& mask);
// The largest 8-connected piece of crown.
Mask largest_piece(const Mask& mask);

}  // namespace fspm::crown
