#pragma once
// The light of a tree's leaf clusters in a scene, as the attribute "light".

#include <cstddef>
#include <cstdint>
#include <span>
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

// Absolute light of a leaf cluster under a real sky (sky_distribution.hpp): the mean PAR flux over
// the period (umol m-2 s-1, night included) and the PAR of a day (mol m-2; the period's divided by
// its days), through the crown swept in voxels of kCanopySweepVoxel_m and the obstacles.
inline constexpr const char* kParAttribute = "par_umol_m2_s";
inline constexpr const char* kDailyParAttribute = "daily_par_mol_m2";

// With a real sky (scene.sky.distribution) the clusters also get kParAttribute and
// kDailyParAttribute (nan elsewhere), and "light" is their share of the period's open PAR through
// the model's sky directions.
void record_leaf_light(TreeGraph& tree, const Scene& scene);
// Only the PAR attributes, for the clusters `spheres` (leaf_spheres) of the tree.
void record_leaf_par(TreeGraph& tree, const Scene& scene, std::span<const Sphere> spheres,
                     std::span<const std::uint32_t> sphere_of);

}  // namespace fspm::environment
