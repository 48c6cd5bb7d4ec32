#pragma once
// The metric light_interception: light the leaf clusters of a tree absorb in a scene.
#include <vector>

#include "environment/occluders.hpp"
#include "environment/scene.hpp"

namespace fspm::experiments {

// Sum of (1 - gamma) pi r^2 i_c over the clusters, i_c the light at the cluster's centre (Pirk
// eq. 4.3) with the cluster itself left out (its own foliage does not shade its centre): the fully
// lit horizontal area that absorbs as much, in m^2.
double light_interception(const environment::Scene& scene,
                          const std::vector<environment::Sphere>& clusters);

}  // namespace fspm::experiments
