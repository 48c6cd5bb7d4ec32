#pragma once
// Silhouette S of a crown mask (Argudo 4.3.2): crown pixels on its border. The connectivity of the
// silhouette curve matters for the inflation (Argudo Fig. 4.13): an 8-connected silhouette (crown
// pixels with a 4-neighbour outside) is one pixel thin and inflates a disc to a sphere; a
// 4-connected one (crown pixels with any of 8 neighbours outside) is thicker on diagonals and gives
// flat or star-shaped crowns.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "crown/raster.hpp"

namespace fspm::crown {

enum class Connectivity : std::uint8_t { kFour, kEight };

enum class PixelClass : std::uint8_t { kOutside, kSilhouette, kInner };

// One class per pixel, row-major. Pixels on the raster border count as having outside neighbours.
std::vector<PixelClass> classify_pixels(const Mask& mask, Connectivity connectivity);

// Where the crown's border passes silhouette pixel (x, y), in pixel coordinates (centres at
// integers). A silhouette pixel's centre lies inside the crown, up to a pixel from its border: a
// disc of radius r has its silhouette centres r - 0.5 from its centre on average, so a crown built
// on them is a pixel narrower and lower than the mask. The centre is moved along the outward normal
// (away from the crown pixels of its 5 x 5 window) to the border. With `coverage` (the share of
// each pixel inside the crown, from a finer mask; empty for a plain mask) the border is placed to
// a fraction of a pixel: across a straight border with normal n it lies (c_p - 1/2) + sum over the
// outside 4-neighbours q of c_q (n . d_q)^2 beyond the centre, 1/2 for a plain mask.
Eigen::Vector2d silhouette_point(const Mask& mask, const Raster& coverage, int x, int y);

}  // namespace fspm::crown
