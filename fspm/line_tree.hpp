#pragma once
// LineTree: the explicit geometry of a plant as a flat list of components in single precision,
// what reconstruction tools hand to renderers and exporters (the "line tree" of Jaeger et al.
// 2010, Table 1). One record per internode, leaf or flower: 45 bytes against TreeGraph's 117,
// and no child lists, so millions of components stream out at memory speed. Parents come before
// their children, as in TreeGraph; to_tree_graph() gives the full TreeGraph when topology
// queries, attributes or double precision are needed.
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <utility>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "fspm/uninitialized_allocator.hpp"

namespace fspm {

class LineTree {
 public:
  template <class T>
  using Column = std::vector<T, UninitializedAllocator<T>>;

  std::size_t size() const { return parent_.size(); }
  bool empty() const { return parent_.empty(); }
  void reserve(std::size_t n);
  void clear();  // keeps the allocated capacity
  std::size_t capacity() const { return parent_.capacity(); }
  // After reserve() for a large plant: huge pages for the columns (see fspm/huge_pages.hpp).
  void advise_huge_pages();
  // Grows every column to n records whose values are unset (the caller writes them all); the
  // `dead` column too when has_dead() is set.
  void resize_for_overwrite(std::size_t n);
  // Adds one record from a TreeGraph node's data (end is implied: start + direction * length).
  NodeId add(NodeId parent, const NodeData& data, bool dead = false);

  // Whether the per-record "dead" flag is kept (GreenLab self-pruning with a pruning period:
  // dead organs still on the plant). Turning it on gives existing records false.
  bool has_dead() const { return has_dead_; }
  void set_has_dead(bool on);

  std::span<const NodeId> parents() const { return parent_; }
  std::span<const Eigen::Vector3f> starts() const { return start_; }
  std::span<const Eigen::Vector3f> directions() const { return direction_; }  // unit headings
  std::span<const float> lengths() const { return length_; }
  std::span<const float> radii() const { return radius_; }
  std::span<const float> birth_times() const { return birth_time_; }
  std::span<const std::uint16_t> physiological_ages() const { return physiological_age_; }
  std::span<const std::uint16_t> orders() const { return order_; }
  std::span<const OrganKind> kinds() const { return kind_; }
  std::span<const std::uint8_t> dead() const { return dead_; }

  // Mutable columns for bulk writers.
  std::span<NodeId> parents() { return parent_; }
  std::span<Eigen::Vector3f> starts() { return start_; }
  std::span<Eigen::Vector3f> directions() { return direction_; }
  std::span<float> lengths() { return length_; }
  std::span<float> radii() { return radius_; }
  std::span<float> birth_times() { return birth_time_; }
  std::span<std::uint16_t> physiological_ages() { return physiological_age_; }
  std::span<std::uint16_t> orders() { return order_; }
  std::span<OrganKind> kinds() { return kind_; }
  std::span<std::uint8_t> dead() { return dead_; }

  Eigen::Vector3f end(NodeId n) const { return start_[n] + direction_[n] * length_[n]; }
  // Bytes per record of the fixed columns (without the optional dead flag).
  static constexpr std::size_t kBytesPerRecord = 45;

  // The same plant as a TreeGraph (double precision; a "dead" attribute when has_dead()).
  TreeGraph to_tree_graph() const;
  // A TreeGraph's nodes in id order (user attributes other than "dead" are dropped).
  static LineTree from_tree_graph(const TreeGraph& tree);

 private:
  Column<NodeId> parent_;
  Column<Eigen::Vector3f> start_, direction_;
  Column<float> length_, radius_, birth_time_;
  Column<std::uint16_t> physiological_age_, order_;
  Column<OrganKind> kind_;
  Column<std::uint8_t> dead_;
  bool has_dead_ = false;
};

}  // namespace fspm
