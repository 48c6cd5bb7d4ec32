#include "fspm/tree_graph_bgl.hpp"

#include <gtest/gtest.h>

#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <random>

#include "tests/fspm/random_tree.hpp"

namespace fspm {
namespace {

BOOST_CONCEPT_ASSERT((boost::IncidenceGraphConcept<TreeGraph>));
BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<TreeGraph>));
BOOST_CONCEPT_ASSERT((boost::AdjacencyGraphConcept<TreeGraph>));

TEST(TreeGraphBgl, BreadthFirstSearchVisitsByDepth) {
  std::mt19937_64 rng(7);
  const TreeGraph t = testing::random_tree(rng, 300, 0);
  std::vector<std::size_t> depth(t.size(), 0);
  struct Recorder : boost::default_bfs_visitor {
    std::vector<std::size_t>* depth;
    std::vector<NodeId>* order;
    void tree_edge(const TreeEdge& e, const TreeGraph&) const {
      (*depth)[e.target] = (*depth)[e.source] + 1;
    }
    void discover_vertex(NodeId v, const TreeGraph&) const { order->push_back(v); }
  };
  std::vector<NodeId> order;
  Recorder vis;
  vis.depth = &depth;
  vis.order = &order;
  std::vector<boost::default_color_type> colors(t.size());
  boost::breadth_first_search(t, 0,
                              boost::visitor(vis).color_map(boost::make_iterator_property_map(
                                  colors.begin(), get(boost::vertex_index, t))));
  ASSERT_EQ(order.size(), t.size());
  // Independent depth: walk up the parent links.
  for (NodeId n = 0; n < t.size(); ++n) {
    std::size_t d = 0;
    for (NodeId m = n; t.parent(m) != kNoNode; m = t.parent(m)) ++d;
    EXPECT_EQ(depth[n], d);
  }
  for (std::size_t i = 1; i < order.size(); ++i) {
    EXPECT_LE(depth[order[i - 1]], depth[order[i]]);
  }
}

TEST(TreeGraphBgl, DijkstraGivesPathLengthFromRoot) {
  std::mt19937_64 rng(8);
  const TreeGraph t = testing::random_tree(rng, 500, 0);
  std::vector<double> dist(t.size());
  std::vector<NodeId> pred(t.size());
  boost::dijkstra_shortest_paths(t, NodeId{0},
                                 boost::weight_map(edge_length_map(t))
                                     .distance_map(boost::make_iterator_property_map(
                                         dist.begin(), get(boost::vertex_index, t)))
                                     .predecessor_map(boost::make_iterator_property_map(
                                         pred.begin(), get(boost::vertex_index, t))));
  for (NodeId n = 1; n < t.size(); ++n) {
    double expected = 0.0;
    for (NodeId m = n; m != 0; m = t.parent(m)) expected += t.length(m);
    EXPECT_NEAR(dist[n], expected, 1e-9 * (1 + expected));
    EXPECT_EQ(pred[n], t.parent(n));
  }
}

}  // namespace
}  // namespace fspm
