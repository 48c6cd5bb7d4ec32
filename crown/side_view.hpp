#pragma once
// The reconstructed crown seen from the side, as a mask, to compare it with a picture of the real
// tree taken at 90 degrees to the photograph (the check of docs/crown.md).
#include "crown/crown_mesh.hpp"
#include "crown/raster.hpp"

namespace fspm::crown {

// Parallel projection of triangles [0, mesh.crown_triangles) seen from +x (image right is +y,
// up is +z, as `fspm render --view side`): a width x height mask at `metres_per_pixel`, the row
// of height z_m = 0 at `ground_row` (the lower edge of that row), y = 0 at the middle column.
Mask side_silhouette(const CrownMesh& mesh, int width, int height, double metres_per_pixel,
                     double ground_row);

// |A and B| / |A or B| after moving B sideways so its mean column meets A's (the two pictures
// need not share the tree's horizontal position). 0 when both are empty.
double intersection_over_union(const Mask& a, const Mask& b);

}  // namespace fspm::crown
