#include "environment/leaf_light.hpp"

#include <cstdint>
#include <limits>
#include <vector>

#include "environment/canopy_sweep.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/sky_distribution.hpp"
#include "fspm/attribute_names.hpp"

namespace fspm::environment {

namespace {

bool is_live_leaf(const TreeGraph& tree, NodeId i, std::span<const double> pruned) {
  return tree.kind(i) == OrganKind::kLeaf && (pruned.empty() || pruned[i] == 0.0);
}

}  // namespace

std::vector<Sphere> leaf_spheres(const TreeGraph& tree, std::vector<std::uint32_t>& sphere_of) {
  const std::span<const double> pruned = tree.has_attribute(kPrunedAttribute)
                                             ? tree.attribute(kPrunedAttribute)
                                             : std::span<const double>{};
  const bool translucent = tree.has_attribute("translucency");
  std::vector<Sphere> spheres;
  sphere_of.assign(tree.size(), kNoSphere);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (!is_live_leaf(tree, i, pruned)) continue;
    sphere_of[i] = static_cast<std::uint32_t>(spheres.size());
    const double gamma = translucent ? tree.attribute("translucency")[i] : 1.0;
    spheres.push_back({tree.start(i), tree.radius(i), gamma, false});
  }
  return spheres;
}

void record_leaf_light(TreeGraph& tree, const Scene& scene) {
  constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::uint32_t> sphere_of;
  const std::vector<Sphere> spheres = leaf_spheres(tree, sphere_of);
  // The growth model's leaf light model (leaf_light_model.hpp), the scene's obstacles by their
  // transmission per sky direction at each cluster.
  const HemisphereDirections dirs(scene.sky.directions);
  std::vector<std::vector<float>> vis(spheres.size());
  std::vector<std::span<const float>> views(spheres.size());
  for (std::size_t k = 0; k < spheres.size(); ++k) {
    vis[k] = obstacle_visibility(scene, dirs, spheres[k].center);
    views[k] = vis[k];
  }
  std::vector<LightSample> lit(spheres.size());
  make_leaf_light_model(kGrowthLeafLightModel, scene.sky)->evaluate(spheres, views, lit);
  tree.add_attribute(kLightAttribute, kNoValue);
  auto light = tree.attribute(kLightAttribute);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (sphere_of[i] != kNoSphere) {
      light[i] = lit[sphere_of[i]].light;
    } else if (tree.kind(i) == OrganKind::kLeaf) {
      light[i] = kNoValue;
    }
  }
  if (scene.sky.distribution) record_leaf_par(tree, scene, spheres, sphere_of);
}

void record_leaf_par(TreeGraph& tree, const Scene& scene, std::span<const Sphere> spheres,
                     std::span<const std::uint32_t> sphere_of) {
  constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> centres;
  centres.reserve(spheres.size());
  for (const Sphere& s : spheres) centres.push_back(s.center);
  const std::vector<DaylightSample> par = daylight_through_voxels(
      spheres, scene, *scene.sky.distribution, centres, kCanopySweepVoxel_m);
  tree.add_attribute(kParAttribute, kNoValue);
  tree.add_attribute(kDailyParAttribute, kNoValue);
  auto flux = tree.attribute(kParAttribute);
  auto daily = tree.attribute(kDailyParAttribute);
  for (NodeId i = 0; i < tree.size(); ++i) {
    const bool lit = sphere_of[i] != kNoSphere;
    flux[i] = lit ? par[sphere_of[i]].par_umol_m2_s : kNoValue;
    daily[i] = lit ? par[sphere_of[i]].daily_par_mol_m2 : kNoValue;
  }
}

}  // namespace fspm::environment
