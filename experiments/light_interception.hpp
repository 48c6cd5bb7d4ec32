#pragma once
// The metric light_interception: light the leaf clusters of a tree absorb in a scene.
#include <map>
#include <string>
#include <vector>

#include "environment/occluders.hpp"
#include "environment/scene.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::experiments {

// Sum of (1 - gamma) pi r^2 i_c over the clusters, i_c the light at the cluster's centre (Pirk
// eq. 4.3) with the cluster itself left out (its own foliage does not shade its centre): the fully
// lit horizontal area that absorbs as much, in m^2.
double light_interception(const environment::Scene& scene,
                          const std::vector<environment::Sphere>& clusters);

// The canopy light metrics (environment/canopy_summary: summarize_canopy_light) of the clusters
// under scene.sky and among the scene's obstacles: sunlit_leaf_area, shaded_leaf_area, star,
// light_interception_efficiency, and absorbed_par when the sky is a real one
// (scene.sky.distribution).
void add_canopy_light_metrics(const environment::Scene& scene,
                              const std::vector<environment::Sphere>& clusters,
                              std::map<std::string, double>& metrics);

// The leaf clusters a tree carries as leaf nodes with a "translucency" attribute, as the growth
// model writes them and plastic adaptation moves them: a sphere at the node's end with its radius
// and translucency. Empty when the tree has none.
std::vector<environment::Sphere> leaf_cluster_spheres(const TreeGraph& tree);

}  // namespace fspm::experiments
