#pragma once
// A quick picture of a reconstructed crown: parallel projection with a depth buffer, vertex
// colours shaded by a light from the picture's upper left and in front, darker with depth, on a
// white background. For checking a
// reconstruction beside its photograph, not for figures of record.
#include "crown/crown_mesh.hpp"
#include "crown/raster.hpp"

namespace fspm::crown {

enum class PreviewView : std::uint8_t { kFront, kSide, kTop };

// kFront looks along +y (as the photograph), kSide along -x (as `fspm render --view side`), kTop
// down along -z with +x to the right and +y (away from the photograph's camera) up the picture.
// The picture has the photograph's size and scale: z = 0 at the lower edge of `ground_row`,
// the crown's axis (x = y = 0) at the middle column (and, from the top, the middle row).
Raster preview(const CrownMesh& mesh, PreviewView view, int width, int height,
               double metres_per_pixel, double ground_row);

}  // namespace fspm::crown
