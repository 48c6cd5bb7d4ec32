#include "fspm/tree_graph.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "fspm/columns.hpp"
#include "fspm/error.hpp"
#include "fspm/huge_pages.hpp"
#include "fspm/name_table.hpp"

namespace fspm {
namespace {

constexpr NameTable<OrganKind, 4> kOrganKindNames{
    "organ kind",
    {{OrganKind::kInternode, "internode", "a stem segment"},
     {OrganKind::kLeaf, "leaf", "a leaf"},
     {OrganKind::kFlower, "flower", "a flower or fruit"},
     {OrganKind::kBud, "bud", "a bud"}}};

}  // namespace

double TreeGraph::bytes_per_node(std::size_t user_attributes) {
  return 4.0 * sizeof(NodeId) + 3.0 * sizeof(Eigen::Vector3d) + 3.0 * sizeof(double) +
         2.0 * sizeof(std::uint16_t) + sizeof(OrganKind) +
         sizeof(double) * static_cast<double>(user_attributes);
}

std::string_view organ_kind_name(OrganKind kind) { return kOrganKindNames.name(kind); }

OrganKind organ_kind_from_name(std::string_view name) { return kOrganKindNames.from_name(name); }

NodeId TreeGraph::add_node(NodeId parent, const NodeData& d) {
  const NodeId id = static_cast<NodeId>(size());
  if (parent == kNoNode) {
    if (!empty())
      throw ValueError("a tree graph has one root; node " + std::to_string(id) +
                       " was given no parent");
  } else if (parent >= size()) {
    throw ValueError("parent " + std::to_string(parent) + " of node " + std::to_string(id) +
                     " does not exist");
  }
  if (size() >= kNoNode - 1) throw ValueError("tree graph is full (2^32 - 2 nodes)");
  // What add_node_unchecked takes as given: a length (negative: the segment's) and a direction
  // (zero or not a number: the segment's, +z for a point).
  NodeData derived = d;
  const Eigen::Vector3d seg = d.end - d.start;
  const double seg_len = seg.norm();
  if (d.length < 0.0) derived.length = seg_len;
  if (!(d.direction.squaredNorm() > 0.0)) {
    derived.direction = seg_len > 0.0 ? Eigen::Vector3d(seg / seg_len) : Eigen::Vector3d::UnitZ();
  }
  return add_node_unchecked(parent, derived);
}

void TreeGraph::reserve(std::size_t n) {
  reserve_columns(n, parent_, first_child_, last_child_, next_sibling_, start_, end_, direction_,
                  length_, radius_, birth_time_, physiological_age_, order_, kind_);
  for (Attribute& a : attributes_) a.values.reserve(n);
}

TreeGraph::Appender::Appender(TreeGraph& graph, std::size_t expected_nodes)
    : graph_(&graph), next_(static_cast<NodeId>(graph.size())) {
  open(graph.size() + std::max<std::size_t>(expected_nodes, 1));
}

void TreeGraph::Appender::open(std::size_t slots) {
  TreeGraph& g = *graph_;
  resize_columns(slots, g.parent_, g.first_child_, g.last_child_, g.next_sibling_, g.start_, g.end_,
                 g.direction_, g.length_, g.radius_, g.birth_time_, g.physiological_age_, g.order_,
                 g.kind_);
  for (Attribute& a : g.attributes_) a.values.resize(slots, a.default_value);
  parent_ = g.parent_.data();
  first_child_ = g.first_child_.data();
  last_child_ = g.last_child_.data();
  next_sibling_ = g.next_sibling_.data();
  start_ = g.start_.data();
  end_point_ = g.end_.data();
  direction_ = g.direction_.data();
  length_ = g.length_.data();
  radius_ = g.radius_.data();
  birth_time_ = g.birth_time_.data();
  physiological_age_ = g.physiological_age_.data();
  order_ = g.order_.data();
  kind_ = g.kind_.data();
  end_ = static_cast<NodeId>(slots);
  open_ = true;
}

void TreeGraph::Appender::grow() { open(2 * static_cast<std::size_t>(end_) + 1); }

void TreeGraph::Appender::finish() {
  if (!open_) return;
  TreeGraph& g = *graph_;
  resize_columns(next_, g.parent_, g.first_child_, g.last_child_, g.next_sibling_, g.start_, g.end_,
                 g.direction_, g.length_, g.radius_, g.birth_time_, g.physiological_age_, g.order_,
                 g.kind_);
  for (Attribute& a : g.attributes_) a.values.resize(next_);
  end_ = next_;  // a later add() opens the columns again
  open_ = false;
}

void TreeGraph::clear() { *this = TreeGraph(); }

void TreeGraph::clear_keep_capacity() {
  clear_columns(parent_, first_child_, last_child_, next_sibling_, start_, end_, direction_,
                length_, radius_, birth_time_, physiological_age_, order_, kind_);
  attributes_.clear();
}

void TreeGraph::advise_huge_pages() {
  advise_huge_page_columns(parent_, first_child_, last_child_, next_sibling_, start_, end_,
                           direction_, length_, radius_, birth_time_, physiological_age_, order_,
                           kind_);
  for (const Attribute& a : attributes_) advise_huge_page_columns(a.values);
}

NodeData TreeGraph::data(NodeId n) const {
  NodeData d;
  d.start = start_[n];
  d.end = end_[n];
  d.direction = direction_[n];
  d.length = length_[n];
  d.radius = radius_[n];
  d.birth_time = birth_time_[n];
  d.physiological_age = physiological_age_[n];
  d.order = order_[n];
  d.kind = kind_[n];
  return d;
}

std::size_t TreeGraph::child_count(NodeId n) const {
  std::size_t c = 0;
  for (NodeId m = first_child_[n]; m != kNoNode; m = next_sibling_[m]) ++c;
  return c;
}

void TreeGraph::set_segment(NodeId n, const Eigen::Vector3d& s, const Eigen::Vector3d& e) {
  start_[n] = s;
  end_[n] = e;
  const Eigen::Vector3d seg = e - s;
  length_[n] = seg.norm();
  if (length_[n] > 0.0) direction_[n] = seg / length_[n];
}

const TreeGraph::Attribute* TreeGraph::find_attribute(std::string_view name) const {
  for (const Attribute& a : attributes_) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

void TreeGraph::add_attribute(const std::string& name, double default_value) {
  if (name.empty()) throw ValueError("attribute names must not be empty");
  if (find_attribute(name) != nullptr) return;
  attributes_.push_back({name, default_value, std::vector<double>(size(), default_value)});
}

bool TreeGraph::has_attribute(std::string_view name) const {
  return find_attribute(name) != nullptr;
}

std::span<double> TreeGraph::attribute(std::string_view name) {
  const Attribute* a = find_attribute(name);
  if (a == nullptr) throw ValueError("the tree has no attribute '" + std::string(name) + "'");
  return const_cast<Attribute*>(a)->values;
}

std::span<const double> TreeGraph::attribute(std::string_view name) const {
  const Attribute* a = find_attribute(name);
  if (a == nullptr) throw ValueError("the tree has no attribute '" + std::string(name) + "'");
  return a->values;
}

double TreeGraph::attribute_default(std::string_view name) const {
  const Attribute* a = find_attribute(name);
  if (a == nullptr) throw ValueError("the tree has no attribute '" + std::string(name) + "'");
  return a->default_value;
}

void TreeGraph::remove_attribute(std::string_view name) {
  std::erase_if(attributes_, [&](const Attribute& a) { return a.name == name; });
}

std::vector<std::string> TreeGraph::attribute_names() const {
  std::vector<std::string> names;
  names.reserve(attributes_.size());
  for (const Attribute& a : attributes_) names.push_back(a.name);
  return names;
}

std::vector<NodeId> TreeGraph::remove_subtree(NodeId n) {
  if (n >= size())
    throw ValueError("remove_subtree: node " + std::to_string(n) + " does not exist");
  // Parents precede children, so one forward pass marks the whole subtree.
  std::vector<char> removed(size(), 0);
  removed[n] = 1;
  for (NodeId i = n + 1; i < size(); ++i) {
    if (parent_[i] != kNoNode && removed[parent_[i]]) removed[i] = 1;
  }
  std::vector<NodeId> remap(size(), kNoNode);
  TreeGraph out;
  out.reserve(size());
  for (const Attribute& a : attributes_) out.add_attribute(a.name, a.default_value);
  for (NodeId i = 0; i < size(); ++i) {
    if (removed[i]) continue;
    const NodeData d = data(i);
    const NodeId p = parent_[i] == kNoNode ? kNoNode : remap[parent_[i]];
    remap[i] = out.add_node(p, d);
    for (std::size_t k = 0; k < attributes_.size(); ++k) {
      out.attributes_[k].values[remap[i]] = attributes_[k].values[i];
    }
  }
  *this = std::move(out);
  return remap;
}

TreeGraph TreeGraph::copy_subtree(NodeId n) const {
  if (n >= size()) throw ValueError("copy_subtree: node " + std::to_string(n) + " does not exist");
  std::vector<NodeId> remap(size(), kNoNode);
  TreeGraph out;
  for (const Attribute& a : attributes_) out.add_attribute(a.name, a.default_value);
  for (NodeId i = n; i < size(); ++i) {
    NodeId p = kNoNode;
    if (i != n) {
      if (parent_[i] == kNoNode || remap[parent_[i]] == kNoNode) continue;
      p = remap[parent_[i]];
    }
    const NodeData d = data(i);
    remap[i] = out.add_node(p, d);
    for (std::size_t k = 0; k < attributes_.size(); ++k) {
      out.attributes_[k].values[remap[i]] = attributes_[k].values[i];
    }
  }
  return out;
}

NodeId TreeGraph::append_subtree(NodeId parent, const TreeGraph& other) {
  if (other.empty()) throw ValueError("append_subtree: the appended graph is empty");
  for (const Attribute& a : other.attributes_) add_attribute(a.name, a.default_value);
  const NodeId offset = static_cast<NodeId>(size());
  for (NodeId i = 0; i < other.size(); ++i) {
    const NodeData d = other.data(i);
    const NodeId p = i == 0 ? parent : other.parent_[i] + offset;
    const NodeId id = add_node(p, d);
    for (const Attribute& a : other.attributes_) {
      attribute(a.name)[id] = a.values[i];
    }
  }
  return offset;
}

namespace {

template <typename T, typename Allocator>
bool bitwise_equal(const std::vector<T, Allocator>& a, const std::vector<T, Allocator>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

}  // namespace

bool TreeGraph::identical(const TreeGraph& o) const {
  if (attributes_.size() != o.attributes_.size()) return false;
  for (std::size_t k = 0; k < attributes_.size(); ++k) {
    const Attribute& a = attributes_[k];
    const Attribute& b = o.attributes_[k];
    if (a.name != b.name ||
        std::bit_cast<std::uint64_t>(a.default_value) !=
            std::bit_cast<std::uint64_t>(b.default_value) ||
        !bitwise_equal(a.values, b.values)) {
      return false;
    }
  }
  return bitwise_equal(parent_, o.parent_) && bitwise_equal(first_child_, o.first_child_) &&
         bitwise_equal(next_sibling_, o.next_sibling_) && bitwise_equal(start_, o.start_) &&
         bitwise_equal(end_, o.end_) && bitwise_equal(direction_, o.direction_) &&
         bitwise_equal(length_, o.length_) && bitwise_equal(radius_, o.radius_) &&
         bitwise_equal(birth_time_, o.birth_time_) &&
         bitwise_equal(physiological_age_, o.physiological_age_) &&
         bitwise_equal(order_, o.order_) && bitwise_equal(kind_, o.kind_);
}

}  // namespace fspm
