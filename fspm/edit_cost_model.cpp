#include "fspm/edit_cost_model.hpp"

#include <cmath>
#include <numeric>

#include "fspm/error.hpp"

namespace fspm {

std::string_view edit_cost_kind_name(EditCostKind kind) { return kEditCostKindNames.name(kind); }

EditCostKind edit_cost_kind_from_name(std::string_view name) {
  return kEditCostKindNames.from_name(name);
}

FeatureCostModel::FeatureCostModel(std::size_t dims, std::vector<double> features_a,
                                   std::vector<double> features_b, double unit_cost)
    : dims_(dims),
      features_a_(std::move(features_a)),
      features_b_(std::move(features_b)),
      unit_cost_(unit_cost) {
  if (!std::isfinite(unit_cost) || unit_cost < 0.0) {
    throw ValueError("cost model: the unit cost must be finite and non-negative");
  }
}

double FeatureCostModel::delete_cost(NodeId a) const {
  double c = unit_cost_;
  for (const double f : features_a(a)) c += std::abs(f);
  return c;
}

double FeatureCostModel::insert_cost(NodeId b) const {
  double c = unit_cost_;
  for (const double f : features_b(b)) c += std::abs(f);
  return c;
}

double FeatureCostModel::relabel_cost(NodeId a, NodeId b) const {
  double c = 0.0;
  const auto fa = features_a(a);
  const auto fb = features_b(b);
  for (std::size_t k = 0; k < dims_; ++k) c += std::abs(fa[k] - fb[k]);
  return c;
}

std::vector<std::string> default_edit_attributes(EditCostKind kind) {
  if (kind == EditCostKind::kTopological) return {};
  return {"length", "radius"};
}

std::vector<double> node_attribute_values(const TreeGraph& tree, std::string_view name) {
  const auto span_values = [](auto values) {
    return std::vector<double>(values.begin(), values.end());
  };
  if (name == "length") return span_values(tree.lengths());
  if (name == "radius" || name == "thickness") return span_values(tree.radii());
  if (name == "birth_time") return span_values(tree.birth_times());
  if (name == "order") return span_values(tree.orders());
  if (name == "physiological_age") return span_values(tree.physiological_ages());
  if (tree.has_attribute(name)) return span_values(tree.attribute(name));
  std::string known = "length, radius, thickness, birth_time, order, physiological_age";
  for (const auto& a : tree.attribute_names()) known += ", " + a;
  throw ValueError("unknown node attribute '" + std::string(name) + "': expected one of " + known);
}

namespace {

std::vector<NodeId> all_nodes(const TreeGraph& t) {
  std::vector<NodeId> ids(t.size());
  std::iota(ids.begin(), ids.end(), NodeId{0});
  return ids;
}

}  // namespace

FeatureCostModel make_edit_cost_model(EditCostKind kind, const TreeGraph& a, const TreeGraph& b,
                                      std::span<const std::string> attributes,
                                      const std::vector<NodeId>* nodes_a,
                                      const std::vector<NodeId>* nodes_b) {
  if (kind == EditCostKind::kTopological) {
    return FeatureCostModel(0, {}, {}, 1.0);
  }
  std::vector<std::string> names(attributes.begin(), attributes.end());
  if (names.empty()) names = default_edit_attributes(kind);
  const std::vector<NodeId> every_a = nodes_a ? std::vector<NodeId>{} : all_nodes(a);
  const std::vector<NodeId> every_b = nodes_b ? std::vector<NodeId>{} : all_nodes(b);
  const auto& compared_a = nodes_a ? *nodes_a : every_a;
  const auto& compared_b = nodes_b ? *nodes_b : every_b;

  const std::size_t dims = names.size();
  std::vector<double> fa(a.size() * dims, 0.0), fb(b.size() * dims, 0.0);
  for (std::size_t k = 0; k < dims; ++k) {
    const auto va = node_attribute_values(a, names[k]);
    const auto vb = node_attribute_values(b, names[k]);
    const auto check = [&](const std::vector<double>& v, const std::vector<NodeId>& ids,
                           const char* tree) {
      for (const NodeId n : ids) {
        if (!std::isfinite(v[n])) {
          throw ValueError("attribute '" + names[k] + "' of node " + std::to_string(n) +
                           " of tree " + tree + " is not a finite number (" + std::to_string(v[n]) +
                           "); the " + std::string(edit_cost_kind_name(kind)) +
                           " cost model needs a value on every compared node");
        }
      }
    };
    check(va, compared_a, "A");
    check(vb, compared_b, "B");
    double mean = 0.0, scale = 1.0;
    if (kind == EditCostKind::kStandardized) {
      // Pirk eq. 4.23: mean and standard deviation over the nodes of both trees together.
      const double n = static_cast<double>(compared_a.size() + compared_b.size());
      double sum = 0.0;
      for (const NodeId i : compared_a) sum += va[i];
      for (const NodeId i : compared_b) sum += vb[i];
      mean = n > 0 ? sum / n : 0.0;
      double ss = 0.0;
      for (const NodeId i : compared_a) ss += (va[i] - mean) * (va[i] - mean);
      for (const NodeId i : compared_b) ss += (vb[i] - mean) * (vb[i] - mean);
      const double sd = n > 1 ? std::sqrt(ss / (n - 1)) : 0.0;
      // Eq. 4.24; with no spread every node has the same value and f is the constant 0.
      scale = sd > 0 ? 1.0 / sd : 0.0;
    }
    for (const NodeId i : compared_a) fa[i * dims + k] = (va[i] - mean) * scale;
    for (const NodeId i : compared_b) fb[i * dims + k] = (vb[i] - mean) * scale;
  }
  return FeatureCostModel(dims, std::move(fa), std::move(fb), 0.0);
}

}  // namespace fspm
