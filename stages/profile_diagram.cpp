#include "stages/profile_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

struct Layers {
  double base_z = 0.0, layer_m = 1.0;
  std::size_t count = 1;
  std::size_t of(double z) const {
    const double k = std::floor((z - base_z) / layer_m);
    return static_cast<std::size_t>(std::clamp(k, 0.0, static_cast<double>(count - 1)));
  }
};

// Adds `amount` spread over [z0, z1] in proportion to the height in each layer (all of it in
// the layer of z0 for a level segment).
void spread(std::vector<double>& into, const Layers& layers, double z0, double z1, double amount) {
  if (z1 < z0) std::swap(z0, z1);
  if (!(z1 - z0 > 1e-12 * layers.layer_m)) {
    into[layers.of(z0)] += amount;
    return;
  }
  for (std::size_t k = layers.of(z0); k <= layers.of(z1); ++k) {
    const double lo = layers.base_z + static_cast<double>(k) * layers.layer_m;
    const double part = std::min(z1, lo + layers.layer_m) - std::max(z0, lo);
    if (part > 0.0) into[k] += amount * part / (z1 - z0);
  }
}

// Per node, the main-axis edge its branch leaves from, or itself for the main axis and the
// organs on it (parents first).
std::vector<NodeId> main_axis_anchor(const TreeGraph& tree,
                                     const std::vector<std::uint32_t>& chain) {
  const auto on_axis = [&](NodeId n) {
    return tree.kind(n) == OrganKind::kInternode && chain[n] == 0;
  };
  std::vector<NodeId> anchor(tree.size(), 0);
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (i == 0 || on_axis(i)) {
      anchor[i] = i;
      continue;
    }
    const NodeId p = tree.parent(i);
    const bool lateral = tree.kind(i) == OrganKind::kInternode;
    anchor[i] = on_axis(p) ? (lateral ? p : i) : anchor[p];
  }
  return anchor;
}

// From the top down: the share of `per_layer`'s total in each layer and above.
std::vector<double> share_above(const std::vector<double>& per_layer) {
  std::vector<double> out(per_layer.size(), 0.0);
  double total = 0.0;
  for (const double v : per_layer) total += v;
  double sum = 0.0;
  for (std::size_t k = per_layer.size(); k-- > 0;) {
    sum += per_layer[k];
    out[k] = total > 0.0 ? sum / total : 0.0;
  }
  return out;
}

}  // namespace

std::string_view clipping_name(Clipping clipping) {
  return clipping == Clipping::kStratified ? "stratified" : "main_axis";
}

ProfileDiagram profile_diagram(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                               double layer_m, Clipping clipping) {
  if (!(layer_m > 0.0) || !std::isfinite(layer_m) || chain.size() != tree.size()) {
    throw ValueError("profile diagram: expected a layer thickness > 0 and one chain per node");
  }
  ProfileDiagram p;
  p.layer_m = layer_m;
  if (tree.empty()) return p;
  Layers layers{tree.start(0).z(), layer_m, 1};
  double top = layers.base_z;
  for (NodeId i = 0; i < tree.size(); ++i)
    top = std::max({top, tree.start(i).z(), tree.end(i).z()});
  layers.count = std::max<std::size_t>(
      1, static_cast<std::size_t>(std::ceil((top - layers.base_z) / layer_m - 1e-9)));
  p.leaves.assign(layers.count, 0.0);
  p.wood_m3.assign(layers.count, 0.0);
  const std::vector<NodeId> anchor = main_axis_anchor(tree, chain);
  for (NodeId i = 0; i < tree.size(); ++i) {
    const bool edge = tree.kind(i) == OrganKind::kInternode;
    if (!edge && tree.kind(i) != OrganKind::kLeaf) continue;
    // MAC puts a branch at the end of the main-axis edge it leaves from.
    const bool moved = clipping == Clipping::kMainAxis && anchor[i] != i;
    const double z0 = moved ? tree.end(anchor[i]).z() : tree.start(i).z();
    const double z1 = moved ? z0 : edge ? tree.end(i).z() : z0;
    if (edge) {
      const double r = tree.radius(i);
      spread(p.wood_m3, layers, z0, z1, std::numbers::pi * r * r * tree.length(i));
    } else {
      p.leaves[layers.of(z0)] += 1.0;
    }
  }
  p.leaves_above = share_above(p.leaves);
  const std::vector<double> wood_above = share_above(p.wood_m3);
  p.tissue_above.resize(layers.count);
  for (std::size_t k = 0; k < layers.count; ++k) {
    p.tissue_above[k] = 0.5 * (p.leaves_above[k] + wood_above[k]);
  }
  return p;
}

}  // namespace fspm::stages
