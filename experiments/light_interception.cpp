#include "experiments/light_interception.hpp"

#include "environment/canopy_summary.hpp"

#include <cstdint>
#include <numbers>

#include "environment/light_model.hpp"

namespace fspm::experiments {

double light_interception(const environment::Scene& scene,
                          const std::vector<environment::Sphere>& clusters) {
  if (clusters.empty()) return 0.0;
  environment::Scene lit = scene;
  const auto first = static_cast<std::uint32_t>(lit.spheres.size());
  lit.spheres.insert(lit.spheres.end(), clusters.begin(), clusters.end());
  const environment::LightModel light(lit);
  double total = 0.0;
  for (std::uint32_t i = 0; i < clusters.size(); ++i) {
    const environment::Sphere& c = clusters[i];
    const double area = std::numbers::pi * c.radius_m * c.radius_m;
    total += (1.0 - c.translucency) * area * light.evaluate(c.center, first + i).light;
  }
  return total;
}

std::vector<environment::Sphere> leaf_cluster_spheres(const TreeGraph& tree) {
  std::vector<environment::Sphere> out;
  if (!tree.has_attribute("translucency")) return out;
  const auto gamma = tree.attribute("translucency");
  for (NodeId n = 0; n < tree.size(); ++n) {
    if (tree.kind(n) != OrganKind::kLeaf || !(tree.radius(n) > 0.0)) continue;
    out.push_back({tree.end(n), tree.radius(n), gamma[n], false});
  }
  return out;
}

void add_canopy_light_metrics(const environment::Scene& scene,
                              const std::vector<environment::Sphere>& clusters,
                              std::map<std::string, double>& metrics) {
  if (clusters.empty()) return;
  const environment::CanopyLightSummary c = environment::summarize_canopy_light(clusters, scene);
  metrics["sunlit_leaf_area"] = c.sunlit_leaf_area_m2;
  metrics["shaded_leaf_area"] = c.shaded_leaf_area_m2;
  metrics["star"] = c.star;
  metrics["light_interception_efficiency"] = c.lie;
  if (c.real_sky) metrics["absorbed_par"] = c.absorbed_par_mol_day;
}

}  // namespace fspm::experiments
