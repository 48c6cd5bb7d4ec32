#pragma once
// Boost.Graph adapter: a TreeGraph is a directed graph with one edge parent -> child, so BGL
// algorithms (breadth_first_search, dijkstra_shortest_paths, ...) run on it directly, without a
// copy. Models IncidenceGraph, VertexListGraph and AdjacencyGraph; vertex_index is the node id;
// edge_length_map(tree) gives the child's length as the edge weight.
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <boost/property_map/property_map.hpp>
#include <utility>

#include "fspm/tree_graph.hpp"

namespace fspm {

struct TreeEdge {
  NodeId source = kNoNode;
  NodeId target = kNoNode;
  bool operator==(const TreeEdge&) const = default;
};

class TreeOutEdgeIterator : public boost::iterator_facade<TreeOutEdgeIterator, TreeEdge,
                                                          std::forward_iterator_tag, TreeEdge> {
 public:
  TreeOutEdgeIterator() = default;
  TreeOutEdgeIterator(NodeId source, TreeGraph::ChildRange::iterator it)
      : source_(source), it_(it) {}

 private:
  friend class boost::iterator_core_access;
  TreeEdge dereference() const { return {source_, *it_}; }
  bool equal(const TreeOutEdgeIterator& o) const { return it_ == o.it_; }
  void increment() { ++it_; }

  NodeId source_ = kNoNode;
  TreeGraph::ChildRange::iterator it_;
};

// Edge weight: the length of the edge's target node (the internode grown along that edge).
class TreeEdgeLengthMap {
 public:
  using key_type = TreeEdge;
  using value_type = double;
  using reference = double;
  using category = boost::readable_property_map_tag;
  explicit TreeEdgeLengthMap(const TreeGraph& g) : g_(&g) {}
  friend double get(const TreeEdgeLengthMap& m, const TreeEdge& e) {
    return m.g_->length(e.target);
  }

 private:
  const TreeGraph* g_;
};

inline TreeEdgeLengthMap edge_length_map(const TreeGraph& g) { return TreeEdgeLengthMap(g); }

}  // namespace fspm

namespace boost {

struct fspm_tree_traversal_tag : virtual incidence_graph_tag,
                                 virtual vertex_list_graph_tag,
                                 virtual adjacency_graph_tag {};

template <>
struct graph_traits<fspm::TreeGraph> {
  using vertex_descriptor = fspm::NodeId;
  using edge_descriptor = fspm::TreeEdge;
  using directed_category = directed_tag;
  using edge_parallel_category = disallow_parallel_edge_tag;
  using traversal_category = fspm_tree_traversal_tag;
  using out_edge_iterator = fspm::TreeOutEdgeIterator;
  using vertex_iterator = counting_iterator<fspm::NodeId>;
  using adjacency_iterator = fspm::TreeGraph::ChildRange::iterator;
  using degree_size_type = std::size_t;
  using vertices_size_type = std::size_t;
  using edges_size_type = std::size_t;
  using in_edge_iterator = void;
  using edge_iterator = void;
  static vertex_descriptor null_vertex() { return fspm::kNoNode; }
};

template <>
struct property_map<fspm::TreeGraph, vertex_index_t> {
  using type = typed_identity_property_map<fspm::NodeId>;
  using const_type = type;
};

}  // namespace boost

namespace fspm {

// Free functions of the BGL concepts, found by argument-dependent lookup.
inline NodeId source(const TreeEdge& e, const TreeGraph&) { return e.source; }
inline NodeId target(const TreeEdge& e, const TreeGraph&) { return e.target; }
inline std::pair<TreeOutEdgeIterator, TreeOutEdgeIterator> out_edges(NodeId v, const TreeGraph& g) {
  const auto r = g.children(v);
  return {TreeOutEdgeIterator(v, r.begin()), TreeOutEdgeIterator(v, r.end())};
}
inline std::size_t out_degree(NodeId v, const TreeGraph& g) { return g.child_count(v); }
inline std::pair<boost::counting_iterator<NodeId>, boost::counting_iterator<NodeId>> vertices(
    const TreeGraph& g) {
  return {boost::counting_iterator<NodeId>(0),
          boost::counting_iterator<NodeId>(static_cast<NodeId>(g.size()))};
}
inline std::size_t num_vertices(const TreeGraph& g) { return g.size(); }
inline std::pair<TreeGraph::ChildRange::iterator, TreeGraph::ChildRange::iterator>
adjacent_vertices(NodeId v, const TreeGraph& g) {
  const auto r = g.children(v);
  return {r.begin(), r.end()};
}
inline boost::typed_identity_property_map<NodeId> get(boost::vertex_index_t, const TreeGraph&) {
  return {};
}

}  // namespace fspm
