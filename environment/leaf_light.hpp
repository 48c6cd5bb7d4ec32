#pragma once
// The light of a tree's leaf clusters in a scene, as the attribute "light".

#include <cstddef>
#include <cstdint>
#include <vector>

#include "environment/scene.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

// Leaf clusters are the tree's nodes of kind leaf: a sphere at the node's start with its radius
// and the attribute "translucency" (1 when absent). Each cluster's "light" becomes the mean sky
// light of its leaves relative to the open sky (the cos^2 sky of Pirk eq. 4.3): the light at its
// centre with every cluster, its own included, shading it as a turbid medium by the path the ray
// travels inside it (CanopyLight::evaluate_clusters, canopy_light.hpp), and the scene's occluders
// by their translucency.
// Pruned leaves (attribute "pruned" != 0) shade nothing and get no value (nan). Internodes keep
// their values (the attribute is added with nan, "no value", when missing).
// The live leaf clusters of a tree (nodes of kind leaf, not pruned) as spheres: centre the node's
// start, its radius, translucency the attribute "translucency" (1 when absent). sphere_of gets
// each node's index among them (kNoSphere for the others).
std::vector<Sphere> leaf_spheres(const TreeGraph& tree, std::vector<std::uint32_t>& sphere_of);

// Crowns of more than kLeafLightVoxelsFrom clusters are evaluated through voxels of
// kLeafLightVoxel_m (LeafAreaGrid).
inline constexpr std::size_t kLeafLightVoxelsFrom = 1000;
inline constexpr double kLeafLightVoxel_m = 0.1;
void record_leaf_light(TreeGraph& tree, const Scene& scene);

}  // namespace fspm::environment
