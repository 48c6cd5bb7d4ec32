#pragma once
// Leaf clusters against solid obstacles (Pirk 4.4.2, Fig. 4.6): a cluster whose sphere enters a
// solid box, sphere or ground is clipped to the largest sphere inside its hull that stays outside
// (its translucency follows the smaller radius, eq. 4.4), or pushed out whole when its centre is
// so deep that less than kMinClippedShare of the radius would remain; member nodes whose ends lie
// inside the solid are moved to its surface ("vertices are moved away from the obstacle").
#include <cstddef>
#include <vector>

#include "environment/scene.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

inline constexpr double kMinClippedShare = 0.25;

// Signed distance from p to a solid occluder of the scene (negative inside) and the outward unit
// normal there; +inf when the scene has no solid occluder.
double signed_distance_to_solids(const Scene& scene, const Eigen::Vector3d& p,
                                 Eigen::Vector3d* normal);

// Clips or pushes the clusters and moves their nodes in `tree`; returns how many clusters changed.
std::size_t push_clusters_out_of_solids(const Scene& scene, TreeGraph& tree,
                                        std::vector<LeafCluster>& clusters);

}  // namespace fspm::environment
