#pragma once
// A trunk under the reconstructed crown: a photograph shows too little of it to reconstruct, so
// it is an open cylinder from the ground into the crown whose height and radius are parameters.
#include "crown/crown_mesh.hpp"

namespace fspm::crown {

// Appends a 12-sided cylinder of `radius_m` from z = 0 to z = top_m around (x, y), bark brown.
// Nothing when the height or radius is not positive.
void append_trunk(CrownMesh& mesh, const Eigen::Vector2f& xy, double top_m, double radius_m);

}  // namespace fspm::crown
