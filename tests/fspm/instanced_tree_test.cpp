// expand_instanced_tree against coordinates worked out by hand.
#include "fspm/instanced_tree.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "fspm/error.hpp"

namespace fspm {
namespace {

NodeData segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  NodeData d;
  d.start = a;
  d.end = b;
  d.radius = 0.1;
  return d;
}

// A trunk of two unit internodes up z, bearing at its top a twig (one internode of length 0.5)
// turned 90 degrees about x, and a second copy of the twig attached to no node, 2 up and with a
// branching order of 3.
InstancedTree trunk_and_twigs() {
  InstancedTree t;
  t.prototypes.resize(2);
  TreeGraph& trunk = t.prototypes[0].geometry;
  const NodeId a = trunk.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  const NodeId b = trunk.add_node(a, segment({0, 0, 1}, {0, 0, 2}));
  trunk.add_attribute("color_index", 0.0);
  trunk.attribute("color_index")[b] = 4.0;
  t.prototypes[1].geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 0.5}));
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(std::acos(-1.0) / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.prototypes[0].children.push_back({1, b, turn, {0, 0, 2}});
  InstancedTree::Child free_twig{1, kNoNode, turn, {0, 0, 2}};
  free_twig.order = 3.0;
  t.prototypes[0].children.push_back(free_twig);
  return t;
}

TEST(InstancedTree, ExpandsOccurrencesWithTheirTransformsOrdersAndAttributes) {
  const TreeGraph g = expand_instanced_tree(trunk_and_twigs(), 100);
  ASSERT_EQ(g.size(), 4u);
  // Rotating (0, 0, 0.5) by 90 degrees about x gives (0, -0.5, 0).
  EXPECT_NEAR((g.end(2) - Eigen::Vector3d(0, -0.5, 2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((g.start(2) - Eigen::Vector3d(0, 0, 2)).norm(), 0.0, 1e-12);
  EXPECT_EQ(g.parent(2), 1u);  // attached to the trunk's top internode
  EXPECT_EQ(g.order(2), 1);
  EXPECT_EQ(g.parent(3), 0u);  // attached to no node: hangs from the root
  EXPECT_EQ(g.order(3), 3);
  EXPECT_EQ(g.attribute("color_index")[1], 4.0);
  EXPECT_EQ(g.attribute("color_index")[2], 0.0);
}

// A one-internode trunk bearing two laterals at its base (at x = 1 and x = -1, one up), each
// bearing a twig at its top: depth first writes a lateral and its twig before the next lateral,
// axis by axis writes both laterals before both twigs.
InstancedTree two_laterals_with_twigs() {
  InstancedTree t;
  t.prototypes.resize(3);
  t.prototypes[0].geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  t.prototypes[1].geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  t.prototypes[2].geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 0.5}));
  const Eigen::Matrix3d same = Eigen::Matrix3d::Identity();
  t.prototypes[0].children.push_back({1, 0, same, {1, 0, 1}});
  t.prototypes[0].children.push_back({1, 0, same, {-1, 0, 1}});
  t.prototypes[1].children.push_back({2, 0, same, {0, 0, 1}});
  return t;
}

TEST(InstancedTree, ExpandsDepthFirstOrAxisByAxis) {
  const InstancedTree t = two_laterals_with_twigs();
  struct Expected {
    NodeId parent;
    Eigen::Vector3d start;
    int order;
  };
  const auto check = [](const TreeGraph& g, const std::vector<Expected>& nodes) {
    ASSERT_EQ(g.size(), nodes.size());
    for (NodeId n = 0; n < g.size(); ++n) {
      EXPECT_EQ(g.parent(n), nodes[n].parent) << n;
      EXPECT_NEAR((g.start(n) - nodes[n].start).norm(), 0.0, 1e-12) << n;
      EXPECT_EQ(g.order(n), nodes[n].order) << n;
    }
  };
  check(expand_instanced_tree(t, 100), {{kNoNode, {0, 0, 0}, 0},
                                        {0, {1, 0, 1}, 1},
                                        {1, {1, 0, 2}, 2},
                                        {0, {-1, 0, 1}, 1},
                                        {3, {-1, 0, 2}, 2}});
  check(expand_instanced_tree(t, 100, ExpansionOrder::kAxisByAxis), {{kNoNode, {0, 0, 0}, 0},
                                                                     {0, {1, 0, 1}, 1},
                                                                     {0, {-1, 0, 1}, 1},
                                                                     {1, {1, 0, 2}, 2},
                                                                     {2, {-1, 0, 2}, 2}});
}

TEST(InstancedTree, RefusesTreesPastTheBudgetAndBadReferences) {
  EXPECT_THROW(expand_instanced_tree(trunk_and_twigs(), 3), ValueError);
  InstancedTree bad = trunk_and_twigs();
  bad.prototypes[0].children[0].prototype = 7;
  EXPECT_THROW(expand_instanced_tree(bad, 100), ValueError);
  InstancedTree cycle;
  cycle.prototypes.resize(1);
  cycle.prototypes[0].children.push_back({0, kNoNode, Eigen::Matrix3d::Identity(), {0, 0, 0}});
  EXPECT_THROW(expand_instanced_tree(cycle, 100), ValueError);
  EXPECT_TRUE(expand_instanced_tree(InstancedTree{}, 100).empty());
}

}  // namespace
}  // namespace fspm
