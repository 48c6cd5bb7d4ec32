#pragma once
// TreeGraph: the explicit skeleton of a plant. One node per internode (metamer) or organ (leaf,
// flower, bud), stored as a structure of arrays so a 10-million-node tree fits in memory:
// 117 bytes per node without user attributes, plus 8 bytes per node per user attribute
// (see docs/formats.md). Node ids are dense indices 0..size()-1, and a parent always has a smaller
// id than its children, so a forward loop over ids is a valid pre-order-compatible topological
// order (parents before children) and files can be streamed.
#include <Eigen/Core>
#include <cstdint>
#include <iterator>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/dcheck.hpp"
#include "fspm/uninitialized_allocator.hpp"

namespace fspm {

using NodeId = std::uint32_t;
inline constexpr NodeId kNoNode = std::numeric_limits<NodeId>::max();

enum class OrganKind : std::uint8_t { kInternode = 0, kLeaf = 1, kFlower = 2, kBud = 3 };

// "internode", "leaf", "flower", "bud".
std::string_view organ_kind_name(OrganKind kind);
// Inverse of organ_kind_name; throws ValueError on an unknown name.
OrganKind organ_kind_from_name(std::string_view name);

// What one node is made of when it is added. Length and direction are derived from start and end
// when left at their defaults (length < 0, direction zero); give them explicitly for organs whose
// extent is not their segment (a leaf attached at a point, a bud).
struct NodeData {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length = -1.0;
  double radius = 0.0;
  double birth_time = 0.0;
  std::uint16_t physiological_age = 1;
  std::uint16_t order = 0;  // branching order: 0 on the trunk, +1 at each lateral branch
  OrganKind kind = OrganKind::kInternode;
};

class TreeGraph {
 public:
  // Forward range over the children of one node, in the order they were added.
  class ChildRange {
   public:
    class iterator {
     public:
      using iterator_category = std::forward_iterator_tag;
      using value_type = NodeId;
      using difference_type = std::ptrdiff_t;
      using pointer = const NodeId*;
      using reference = NodeId;
      iterator() = default;
      iterator(const TreeGraph* g, NodeId n) : g_(g), n_(n) {}
      NodeId operator*() const { return n_; }
      iterator& operator++() {
        n_ = g_->next_sibling_[n_];
        return *this;
      }
      iterator operator++(int) {
        iterator old = *this;
        ++*this;
        return old;
      }
      bool operator==(const iterator& o) const { return n_ == o.n_; }

     private:
      const TreeGraph* g_ = nullptr;
      NodeId n_ = kNoNode;
    };
    ChildRange(const TreeGraph* g, NodeId first) : g_(g), first_(first) {}
    iterator begin() const { return {g_, first_}; }
    iterator end() const { return {g_, kNoNode}; }
    bool empty() const { return first_ == kNoNode; }

   private:
    const TreeGraph* g_;
    NodeId first_;
  };

  TreeGraph() = default;

  // Adds a node under `parent` (kNoNode for the root; a graph has exactly one root, id 0).
  // Throws ValueError for an unknown parent or a second root.
  NodeId add_node(NodeId parent, const NodeData& data);
  // add_node for bulk builders that guarantee validity themselves (reconstruction): no checks
  // (`parent` must be an existing node, kNoNode only for the first one) and length and direction
  // taken as given (data.length >= 0, data.direction the unit heading), so nothing is derived.
  // Inline so that tight loops avoid the call; after reserve() it never reallocates.
  NodeId add_node_unchecked(NodeId parent, const NodeData& data) {
    FSPM_DCHECK(parent == kNoNode ? parent_.empty() : parent < parent_.size(),
                "add_node_unchecked: an existing parent, or kNoNode for the first node only");
    const NodeId id = static_cast<NodeId>(parent_.size());
    parent_.push_back(parent);
    first_child_.push_back(kNoNode);
    last_child_.push_back(kNoNode);
    next_sibling_.push_back(kNoNode);
    if (parent != kNoNode) {
      NodeId& last = last_child_[parent];
      (last == kNoNode ? first_child_[parent] : next_sibling_[last]) = id;
      last = id;
    }
    start_.push_back(data.start);
    end_.push_back(data.end);
    direction_.push_back(data.direction);
    length_.push_back(data.length);
    radius_.push_back(data.radius);
    birth_time_.push_back(data.birth_time);
    physiological_age_.push_back(data.physiological_age);
    order_.push_back(data.order);
    kind_.push_back(data.kind);
    for (Attribute& a : attributes_) a.values.push_back(a.default_value);
    return id;
  }
  void reserve(std::size_t nodes);

  // Appends many nodes at the speed of the memory: the columns grow once by an expected count,
  // and add() writes one node through raw pointers, without a capacity check and size update per
  // column (2-2.5x faster than add_node_unchecked for a stage of tens of thousands of nodes).
  // add() takes what add_node_unchecked takes; past the expected count it grows the columns
  // again. finish() (or the destructor) drops the slots left unused, and only then is the graph
  // whole again: until then, read only nodes already added (parent(), end(), ...) and change
  // the graph through nothing else.
  class Appender {
   public:
    Appender(TreeGraph& graph, std::size_t expected_nodes);
    ~Appender() { finish(); }
    Appender(const Appender&) = delete;
    Appender& operator=(const Appender&) = delete;

    NodeId add(NodeId parent, const NodeData& data) {
      if (next_ == end_) [[unlikely]]
        grow();
      FSPM_DCHECK(parent == kNoNode ? next_ == 0 : parent < next_,
                  "Appender::add: an existing parent, or kNoNode for the first node only");
      const NodeId id = next_++;
      parent_[id] = parent;
      first_child_[id] = last_child_[id] = next_sibling_[id] = kNoNode;
      if (parent != kNoNode) {
        NodeId& last = last_child_[parent];
        (last == kNoNode ? first_child_[parent] : next_sibling_[last]) = id;
        last = id;
      }
      start_[id] = data.start;
      end_point_[id] = data.end;
      direction_[id] = data.direction;
      length_[id] = data.length;
      radius_[id] = data.radius;
      birth_time_[id] = data.birth_time;
      physiological_age_[id] = data.physiological_age;
      order_[id] = data.order;
      kind_[id] = data.kind;
      return id;
    }
    // Nodes in the graph so far, the ones added included.
    std::size_t size() const { return next_; }
    void finish();

   private:
    void grow();
    void open(std::size_t slots);  // columns sized to `slots`, pointers taken

    TreeGraph* graph_;
    NodeId next_ = 0, end_ = 0;
    bool open_ = false;
    NodeId *parent_ = nullptr, *first_child_ = nullptr, *last_child_ = nullptr,
           *next_sibling_ = nullptr;
    Eigen::Vector3d *start_ = nullptr, *end_point_ = nullptr, *direction_ = nullptr;
    double *length_ = nullptr, *radius_ = nullptr, *birth_time_ = nullptr;
    std::uint16_t *physiological_age_ = nullptr, *order_ = nullptr;
    OrganKind* kind_ = nullptr;
  };
  void clear();
  // Like clear(), but the node columns keep their allocated capacity, so a graph rebuilt again
  // and again (growth animation frames, benchmarks) neither reallocates nor faults its memory in
  // anew. User attributes are removed.
  void clear_keep_capacity();
  std::size_t capacity() const { return parent_.capacity(); }
  // After reserve() for a very large graph: asks Linux to back the reserved columns with
  // transparent huge pages (madvise MADV_HUGEPAGE), so faulting in hundreds of megabytes takes a
  // few hundred faults instead of ~50 000 per 200 MB. Only a hint; a no-op on other systems.
  void advise_huge_pages();

  std::size_t size() const { return parent_.size(); }
  // Bytes one node takes: the fixed columns (117 bytes) and one double per user attribute; the
  // estimate every producer of trees checks against the memory limit before it allocates.
  static double bytes_per_node(std::size_t user_attributes);
  bool empty() const { return parent_.empty(); }
  NodeId root() const { return empty() ? kNoNode : 0; }

  NodeId parent(NodeId n) const { return parent_[n]; }
  ChildRange children(NodeId n) const { return {this, first_child_[n]}; }
  NodeId first_child(NodeId n) const { return first_child_[n]; }
  NodeId next_sibling(NodeId n) const { return next_sibling_[n]; }
  std::size_t child_count(NodeId n) const;
  bool is_tip(NodeId n) const { return first_child_[n] == kNoNode; }

  const Eigen::Vector3d& start(NodeId n) const { return start_[n]; }
  const Eigen::Vector3d& end(NodeId n) const { return end_[n]; }
  const Eigen::Vector3d& direction(NodeId n) const { return direction_[n]; }
  double length(NodeId n) const { return length_[n]; }
  double radius(NodeId n) const { return radius_[n]; }
  double birth_time(NodeId n) const { return birth_time_[n]; }
  std::uint16_t physiological_age(NodeId n) const { return physiological_age_[n]; }
  std::uint16_t order(NodeId n) const { return order_[n]; }
  OrganKind kind(NodeId n) const { return kind_[n]; }
  // All fixed columns of one node (not the user attributes).
  NodeData data(NodeId n) const;

  // Setters keep length and direction as given; call set_segment to move a node's ends and
  // recompute both.
  void set_segment(NodeId n, const Eigen::Vector3d& start, const Eigen::Vector3d& end);
  void set_radius(NodeId n, double radius) { radius_[n] = radius; }
  void set_birth_time(NodeId n, double t) { birth_time_[n] = t; }
  void set_physiological_age(NodeId n, std::uint16_t age) { physiological_age_[n] = age; }
  void set_order(NodeId n, std::uint16_t order) { order_[n] = order; }
  void set_kind(NodeId n, OrganKind kind) { kind_[n] = kind; }
  void set_direction(NodeId n, const Eigen::Vector3d& d) { direction_[n] = d; }
  void set_length(NodeId n, double length) { length_[n] = length; }

  // Whole columns, for fast loops and zero-copy export (Python, writers).
  std::span<const NodeId> parents() const { return parent_; }
  std::span<const Eigen::Vector3d> starts() const { return start_; }
  std::span<const Eigen::Vector3d> ends() const { return end_; }
  std::span<const Eigen::Vector3d> directions() const { return direction_; }
  std::span<const double> lengths() const { return length_; }
  std::span<const double> radii() const { return radius_; }
  std::span<const double> birth_times() const { return birth_time_; }
  std::span<const std::uint16_t> physiological_ages() const { return physiological_age_; }
  std::span<const std::uint16_t> orders() const { return order_; }
  std::span<const OrganKind> kinds() const { return kind_; }

  // User attributes: named columns of doubles, one value per node. New nodes get the column's
  // default value. Adding an existing name keeps its values.
  void add_attribute(const std::string& name, double default_value = 0.0);
  bool has_attribute(std::string_view name) const;
  // Throws ValueError when there is no such attribute.
  std::span<double> attribute(std::string_view name);
  std::span<const double> attribute(std::string_view name) const;
  double attribute_default(std::string_view name) const;
  void remove_attribute(std::string_view name);
  std::vector<std::string> attribute_names() const;

  // Removes the subtree rooted at n (n included; removing the root empties the graph). Ids are
  // compacted keeping their relative order; returns the map old id -> new id (kNoNode if removed).
  std::vector<NodeId> remove_subtree(NodeId n);
  // Copy of the subtree rooted at n as a new graph whose root is n's copy.
  TreeGraph copy_subtree(NodeId n) const;
  // Appends `other` under `parent` (kNoNode only if this graph is empty); returns the new id of
  // other's root. Attributes missing on either side are added with their defaults.
  NodeId append_subtree(NodeId parent, const TreeGraph& other);

  // Exact equality of structure, all columns and attributes (bitwise for doubles, so NaN == NaN).
  bool identical(const TreeGraph& other) const;

 private:
  struct Attribute {
    std::string name;
    double default_value;
    std::vector<double> values;
  };
  const Attribute* find_attribute(std::string_view name) const;

  // Columns grow without zeros (UninitializedAllocator): only Appender grows them by resize(),
  // and it writes every slot it keeps.
  template <typename T>
  using Column = std::vector<T, UninitializedAllocator<T>>;
  Column<NodeId> parent_, first_child_, last_child_, next_sibling_;
  Column<Eigen::Vector3d> start_, end_, direction_;
  Column<double> length_, radius_, birth_time_;
  Column<std::uint16_t> physiological_age_, order_;
  Column<OrganKind> kind_;
  std::vector<Attribute> attributes_;
};

}  // namespace fspm
