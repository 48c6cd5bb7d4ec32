#pragma once
// Sky seen through gaps of a sparse crown is not crown texture: inside the crown mask, pixels that
// are not foliage take the colour of the foliage around them (a normalized Gaussian average over
// the foliage pixels, widened until every gap is reached), so that neither the synthesized
// texture nor the front of the mesh shows sky, and gaps do not read as bumps in the relief.
#include "crown/raster.hpp"

namespace fspm::crown {

// `foliage`: pixels holding crown texture. Pixels of `crown` outside it get filled; the rest of
// the photograph is returned unchanged. A crown without any foliage pixel is returned as it is.
Raster fill_gaps(const Raster& rgb, const Mask& crown, const Mask& foliage);

}  // namespace fspm::crown
