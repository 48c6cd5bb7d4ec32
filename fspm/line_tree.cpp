#include "fspm/line_tree.hpp"

#include "fspm/attribute_names.hpp"
#include "fspm/columns.hpp"
#include "fspm/huge_pages.hpp"

namespace fspm {

void LineTree::reserve(std::size_t n) {
  reserve_columns(n, parent_, start_, direction_, length_, radius_, birth_time_, physiological_age_,
                  order_, kind_);
  if (has_dead_) dead_.reserve(n);
}

void LineTree::advise_huge_pages() {
  advise_huge_page_columns(parent_, start_, direction_, length_, radius_, birth_time_,
                           physiological_age_, order_, kind_, dead_);
}

void LineTree::clear() {
  clear_columns(parent_, start_, direction_, length_, radius_, birth_time_, physiological_age_,
                order_, kind_, dead_);
}

void LineTree::resize_for_overwrite(std::size_t n) {
  resize_columns(n, parent_, start_, direction_, length_, radius_, birth_time_, physiological_age_,
                 order_, kind_);
  if (has_dead_) dead_.resize(n);
}

void LineTree::set_has_dead(bool on) {
  has_dead_ = on;
  if (on) {
    dead_.assign(size(), 0);
  } else {
    dead_.clear();
  }
}

NodeId LineTree::add(NodeId parent, const NodeData& data, bool dead) {
  const auto id = static_cast<NodeId>(size());
  parent_.push_back(parent);
  start_.push_back(data.start.cast<float>());
  direction_.push_back(data.direction.cast<float>());
  length_.push_back(static_cast<float>(data.length));
  radius_.push_back(static_cast<float>(data.radius));
  birth_time_.push_back(static_cast<float>(data.birth_time));
  physiological_age_.push_back(data.physiological_age);
  order_.push_back(data.order);
  kind_.push_back(data.kind);
  if (has_dead_) dead_.push_back(dead ? 1 : 0);
  return id;
}

TreeGraph LineTree::to_tree_graph() const {
  TreeGraph tree;
  tree.reserve(size());
  if (has_dead_) tree.add_attribute(kDeadAttribute, 0.0);
  NodeData d;
  for (NodeId n = 0; n < size(); ++n) {
    d.start = start_[n].cast<double>();
    d.direction = direction_[n].cast<double>();
    d.length = length_[n];
    d.end = d.start + d.direction * d.length;
    d.radius = radius_[n];
    d.birth_time = birth_time_[n];
    d.physiological_age = physiological_age_[n];
    d.order = order_[n];
    d.kind = kind_[n];
    // add_node checks the parent (a hand-made LineTree may be wrong); length and direction are
    // kept as given because the length is not negative.
    tree.add_node(parent_[n], d);
    if (has_dead_ && dead_[n]) tree.attribute(kDeadAttribute)[n] = 1.0;
  }
  return tree;
}

LineTree LineTree::from_tree_graph(const TreeGraph& tree) {
  LineTree lines;
  const bool dead = tree.has_attribute(kDeadAttribute);
  lines.set_has_dead(dead);
  lines.reserve(tree.size());
  for (NodeId n = 0; n < tree.size(); ++n) {
    lines.add(tree.parent(n), tree.data(n), dead && tree.attribute(kDeadAttribute)[n] != 0.0);
  }
  return lines;
}

}  // namespace fspm
