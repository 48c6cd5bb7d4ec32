#pragma once
// Costs of the edit operations of the constrained edit distance (Pirk sec. 4.5.3):
//   topological   delete = insert = 1, relabel = 0 (Levenshtein-like, Ferraro and Godin 2000);
//   absolute      relabel sum_k |a_k - b_k|, delete/insert sum_k |a_k| over a list of attributes;
//   standardized  the same on attributes standardized over both trees together (Pirk eq.
//                 4.23-4.26), default attributes branch length and radius.
// Every model must keep relabel(a, b) <= delete(a) + insert(b); see constrained_edit_distance.hpp
// for why the dynamic programme needs it.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/name_table.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

enum class EditCostKind { kTopological, kAbsolute, kStandardized };

inline constexpr NameTable<EditCostKind, 3> kEditCostKindNames{
    "cost model",
    {{EditCostKind::kTopological, "topological", "delete and insert cost 1, relabel 0"},
     {EditCostKind::kAbsolute, "absolute", "costs from the attribute values and their differences"},
     {EditCostKind::kStandardized, "standardized",
      "the same on attributes standardized over both trees, Pirk eq. 4.23-4.26"}}};
inline constexpr auto kEditCostKinds = kEditCostKindNames.values();

// "topological", "absolute", "standardized".
std::string_view edit_cost_kind_name(EditCostKind kind);
// Inverse of edit_cost_kind_name; throws ValueError on an unknown name.
EditCostKind edit_cost_kind_from_name(std::string_view name);

// Costs for one pair of trees A (source) and B (target), by node id of each tree. Implement it
// for a custom model; the distance rejects a model with a negative or non-finite cost or with
// relabel(a, b) > delete(a) + insert(b) for some pair it compares (ValueError).
class EditCostModel {
 public:
  virtual ~EditCostModel() = default;
  virtual double delete_cost(NodeId a) const = 0;
  virtual double insert_cost(NodeId b) const = 0;
  virtual double relabel_cost(NodeId a, NodeId b) const = 0;
};

// Manhattan costs on per-node feature vectors f (dims values per node):
//   relabel = sum_k |f_k(a) - f_k(b)|, delete = unit + sum_k |f_k(a)|, insert = unit + sum_k
//   |f_k(b)|.
// |x - y| <= |x| + |y| makes relabel <= delete + insert hold by construction.
class FeatureCostModel final : public EditCostModel {
 public:
  // features_a holds dims values per node of A (node-major), features_b likewise for B.
  FeatureCostModel(std::size_t dims, std::vector<double> features_a, std::vector<double> features_b,
                   double unit_cost);
  std::size_t dims() const { return dims_; }
  double unit_cost() const { return unit_cost_; }
  // data() + offset, not &v[i]: with zero dimensions the vectors are empty and indexing them is
  // undefined behaviour.
  std::span<const double> features_a(NodeId a) const {
    return {features_a_.data() + std::size_t{a} * dims_, dims_};
  }
  std::span<const double> features_b(NodeId b) const {
    return {features_b_.data() + std::size_t{b} * dims_, dims_};
  }

  double delete_cost(NodeId a) const override;
  double insert_cost(NodeId b) const override;
  double relabel_cost(NodeId a, NodeId b) const override;

 private:
  std::size_t dims_;
  std::vector<double> features_a_, features_b_;
  double unit_cost_;
};

// The attributes a model compares by default: none for topological, {"length", "radius"}
// (branch length and thickness, as Pirk) otherwise.
std::vector<std::string> default_edit_attributes(EditCostKind kind);

// One value per node of a named attribute: "length", "radius" (alias "thickness"),
// "birth_time", "order", "physiological_age", or a user attribute of the tree (Newick labels are
// the user attribute "label"). Throws ValueError for an unknown name.
std::vector<double> node_attribute_values(const TreeGraph& tree, std::string_view name);

// Builds a built-in model for trees a and b. `attributes` empty means default_edit_attributes.
// The standardized model takes its means and standard deviations (eq. 4.23, divisor n - 1) over
// the compared nodes of both trees together: `nodes_a` / `nodes_b` when given, else all nodes.
// An attribute with zero spread standardizes to 0 (the constant of eq. 4.24). Throws ValueError
// when a compared node has a NaN or infinite attribute value.
FeatureCostModel make_edit_cost_model(EditCostKind kind, const TreeGraph& a, const TreeGraph& b,
                                      std::span<const std::string> attributes = {},
                                      const std::vector<NodeId>* nodes_a = nullptr,
                                      const std::vector<NodeId>* nodes_b = nullptr);

}  // namespace fspm
