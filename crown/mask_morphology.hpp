#pragma once
// Binary morphology on crown masks with a square structuring element, and the connected-piece
// helpers the automatic mask needs.
#include "crown/raster.hpp"

namespace fspm::crown {

Mask dilate(const Mask& mask, int radius);
Mask erode(const Mask& mask, int radius);
// Background pixels not connected (4-neighbours) to the raster border become crown.
Mask fill_holes(const Mask& mask);
// The 8-connected pieces of crown whose area is at least `fraction` of the largest one's.
Mask large_pieces(const Mask& mask, double fraction);

}  // namespace fspm::crown
