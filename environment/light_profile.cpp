#include "environment/light_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fspm/attribute_names.hpp"

namespace fspm::environment {

std::vector<LightLayer> leaf_light_profile(const TreeGraph& tree, int layers) {
  layers = std::max(layers, 1);
  if (tree.size() == 0 || !tree.has_attribute(kLightAttribute)) return {};
  const auto light = tree.attribute(kLightAttribute);
  const bool has_pruned = tree.has_attribute(kPrunedAttribute);
  const double base = tree.start(0).z();
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<NodeId> leaves;
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (tree.kind(i) != OrganKind::kLeaf || !std::isfinite(light[i])) continue;
    if (has_pruned && tree.attribute(kPrunedAttribute)[i] != 0.0) continue;
    leaves.push_back(i);
    lo = std::min(lo, tree.start(i).z());
    hi = std::max(hi, tree.start(i).z());
  }
  if (leaves.empty()) return {};
  const double thickness = hi > lo ? (hi - lo) / layers : 1.0;
  std::vector<double> sum(static_cast<std::size_t>(layers), 0.0);
  std::vector<int> count(static_cast<std::size_t>(layers), 0);
  for (const NodeId i : leaves) {
    const auto k = static_cast<std::size_t>(
        std::clamp(static_cast<int>((tree.start(i).z() - lo) / thickness), 0, layers - 1));
    sum[k] += light[i];
    ++count[k];
  }
  std::vector<LightLayer> out;
  for (int k = 0; k < layers; ++k) {
    const auto at = static_cast<std::size_t>(k);
    if (count[at] == 0) continue;
    out.push_back({lo + (k + 0.5) * thickness - base, sum[at] / count[at], count[at]});
  }
  return out;
}

}  // namespace fspm::environment
