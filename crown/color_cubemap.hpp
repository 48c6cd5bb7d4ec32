#pragma once
// Colour cubemap of a crown (Argudo 4.5.2): the four lateral faces come from one synthesized strip
// of (4N + B) x (N + 2B) pixels made horizontally tileable by a minimum-error seam between its
// first and last B columns; top and bottom are synthesized N x N and joined to the strip's B extra
// rows above and below the lateral faces. Argudo joins those bands by graph cuts; here they are
// feathered (linear blend over the band), which hides the join as well on foliage texture.
#include <random>

#include "crown/cubemap.hpp"
#include "crown/texture_synthesis.hpp"

namespace fspm::crown {

// B = N / 8 as in Argudo's tests. Throws like quilt_texture.
Cubemap color_cubemap(const Raster& rgb, const Mask& mask, int size, const QuiltOptions& options,
                      std::mt19937_64& rng);

// Makes a strip wider than 4N tileable: its last `band` columns are cut into its first ones along
// the minimum-error seam; returns the 4N-wide strip.
Raster tileable_strip(const Raster& strip, int band);

}  // namespace fspm::crown
