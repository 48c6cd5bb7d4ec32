#include "environment/leaf_light.hpp"

#include <cstdint>
#include <limits>
#include <vector>

#include "environment/light_model.hpp"
#include "fspm/attribute_names.hpp"

namespace fspm::environment {

namespace {

bool is_live_leaf(const TreeGraph& tree, NodeId i, std::span<const double> pruned) {
  return tree.kind(i) == OrganKind::kLeaf && (pruned.empty() || pruned[i] == 0.0);
}

// Appends the live leaves of `tree` to the scene's spheres; returns each node's sphere index.
std::vector<std::uint32_t> add_leaf_spheres(const TreeGraph& tree, Scene& s) {
  const std::span<const double> pruned = tree.has_attribute(kPrunedAttribute)
                                             ? tree.attribute(kPrunedAttribute)
                                             : std::span<const double>{};
  const bool translucent = tree.has_attribute("translucency");
  std::vector<std::uint32_t> sphere_of(tree.size(), kNoSphere);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (!is_live_leaf(tree, i, pruned)) continue;
    sphere_of[i] = static_cast<std::uint32_t>(s.spheres.size());
    const double gamma = translucent ? tree.attribute("translucency")[i] : 1.0;
    s.spheres.push_back({tree.start(i), tree.radius(i), gamma, false});
  }
  return sphere_of;
}

}  // namespace

void record_leaf_light(TreeGraph& tree, const Scene& scene) {
  constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
  Scene s = scene;
  const std::vector<std::uint32_t> sphere_of = add_leaf_spheres(tree, s);
  const LightModel model(s);
  tree.add_attribute(kLightAttribute, kNoValue);
  auto light = tree.attribute(kLightAttribute);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (sphere_of[i] != kNoSphere) {
      light[i] = model.evaluate(tree.start(i), sphere_of[i]).light;
    } else if (tree.kind(i) == OrganKind::kLeaf) {
      light[i] = kNoValue;
    }
  }
}

}  // namespace fspm::environment
