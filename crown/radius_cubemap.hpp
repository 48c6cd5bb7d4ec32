#pragma once
// Radius cubemap (Argudo 4.6): the distance from the crown centre to its surface in every
// direction. Argudo renders the mesh into the cubemap; here every texel takes the distance along
// its direction to the triangles it passes through (the largest: the outer surface), every
// vertex is also splatted into its texel (for the few triangles across a face's plane), and
// texels left empty take the mean of their filled neighbours.
#include <Eigen/Core>

#include "crown/crown_mesh.hpp"
#include "crown/cubemap.hpp"

namespace fspm::crown {

// One channel, metres. Vertices of triangles [0, mesh.crown_triangles) only.
Cubemap radius_cubemap(const CrownMesh& mesh, const Eigen::Vector3f& centre, int size);

// Height cubemap (Argudo 4.6 step 3): the luminance heightfield of every colour face, in [0, 1].
Cubemap height_cubemap(const Cubemap& color, int levels);

// Bilinear-free lookup: the texel value in `direction` (channel 0).
float sample(const Cubemap& cubemap, const Eigen::Vector3f& direction);

}  // namespace fspm::crown
