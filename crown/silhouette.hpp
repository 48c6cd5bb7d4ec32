#pragma once
// Silhouette S of a crown mask (Argudo 4.3.2): crown pixels on its border. The connectivity of the
// silhouette curve matters for the inflation (Argudo Fig. 4.13): an 8-connected silhouette (crown
// pixels with a 4-neighbour outside) is one pixel thin and inflates a disc to a sphere; a
// 4-connected one (crown pixels with any of 8 neighbours outside) is thicker on diagonals and gives
// flat or star-shaped crowns.
#include <cstdint>
#include <vector>

#include "crown/raster.hpp"

namespace fspm::crown {

enum class Connectivity : std::uint8_t { kFour, kEight };

enum class PixelClass : std::uint8_t { kOutside, kSilhouette, kInner };

// One class per pixel, row-major. Pixels on the raster border count as having outside neighbours.
std::vector<PixelClass> classify_pixels(const Mask& mask, Connectivity connectivity);

}  // namespace fspm::crown
