// Instanced trees as .ctree version 2 graphs, against trees worked out by hand.
#include "fspm/instanced_ctree.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>

#include "fspm/error.hpp"

namespace fspm {
namespace {

NodeData segment(const Eigen::Vector3d& start, const Eigen::Vector3d& end) {
  NodeData d;
  d.start = start;
  d.end = end;
  d.radius = 0.1;
  return d;
}

// A trunk of two unit internodes up z; a branch prototype (one unit internode up z) placed twice
// at the top of the first internode, turned +90 and -90 degrees about x, and once, from no node,
// at the trunk's base turned 180 degrees about z. The explicit tree, by hand: 2 + 3 = 5 nodes;
// the placed branches start at (0, 0, 1) and end at (0, -1, 1) and (0, 1, 1) (a +90 degree turn
// about x takes z to -y), the loose one ends at (0, 0, 1) (a turn about z keeps z).
InstancedTree hand_tree() {
  InstancedTree t;
  InstancedTree::Prototype trunk, branch;
  const NodeId base = trunk.geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  trunk.geometry.add_node(base, segment({0, 0, 1}, {0, 0, 2}));
  trunk.geometry.add_attribute("color_index");
  trunk.geometry.attribute("color_index")[1] = 3.0;
  branch.geometry.add_node(kNoNode, segment({0, 0, 0}, {0, 0, 1}));
  const double half_pi = std::numbers::pi / 2;
  InstancedTree::Child up;
  up.prototype = 1;
  up.attach = base;
  up.rotation = Eigen::AngleAxisd(half_pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  up.translation = {0, 0, 1};
  InstancedTree::Child down = up;
  down.rotation = Eigen::AngleAxisd(-half_pi, Eigen::Vector3d::UnitX()).toRotationMatrix();
  InstancedTree::Child loose;
  loose.prototype = 1;
  loose.attach = kNoNode;
  loose.rotation = Eigen::AngleAxisd(std::numbers::pi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  trunk.children = {up, down, loose};
  t.prototypes = {trunk, branch};
  return t;
}

TEST(InstancedCtree, RecordsAndMultiplicitiesOfAHandTree) {
  const CompressedTreeGraph g = compress_instanced_tree(hand_tree());
  // Group 0, trunk nodes 1 and 2, group 3, branch node 4.
  ASSERT_EQ(g.size(), 5u);
  EXPECT_TRUE(g.has_geometry());
  EXPECT_EQ(g.root(), 0u);
  EXPECT_TRUE(g.geometry.records[0].group);
  EXPECT_TRUE(g.geometry.records[3].group);
  EXPECT_EQ(g.record(1).successor, 2u);
  EXPECT_EQ(g.axillaries(1).size(), 2u);  // the two placed branches
  EXPECT_EQ(g.record(3).multiplicity, 3u);
  EXPECT_EQ(g.record(4).multiplicity, 3u);
  EXPECT_EQ(geometry_organ_count(g), 5u);
  EXPECT_EQ(g.geometry.placements.size(), 3u);
  EXPECT_EQ(g.geometry.attributes.at("color_index")[2], 3.0);
  EXPECT_EQ(g.geometry.attributes.at("color_index")[4], 0.0);  // absent from the branch
}

TEST(InstancedCtree, EncodedVersionTwoReadsBackAndExpandsAsByHand) {
  const std::string bytes = encode_ctree(compress_instanced_tree(hand_tree()));
  EXPECT_EQ(bytes[8], 2);  // version 2: geometry follows the records
  const TreeGraph t = expand_instanced_tree(instanced_tree_of(decode_ctree(bytes)), 100);
  ASSERT_EQ(t.size(), 5u);
  std::vector<Eigen::Vector3d> ends;
  for (NodeId n = 0; n < t.size(); ++n) ends.push_back(t.end(n));
  auto has_end = [&](const Eigen::Vector3d& p) {
    return std::any_of(ends.begin(), ends.end(),
                       [&](const auto& e) { return (e - p).norm() < 1e-12; });
  };
  EXPECT_TRUE(has_end({0, 0, 2}));
  EXPECT_TRUE(has_end({0, -1, 1}));
  EXPECT_TRUE(has_end({0, 1, 1}));
  EXPECT_EQ(
      std::count_if(ends.begin(), ends.end(),
                    [](const auto& e) { return (e - Eigen::Vector3d(0, 0, 1)).norm() < 1e-12; }),
      2);
  EXPECT_EQ(t.attribute("color_index")[t.first_child(0)], 3.0);
}

TEST(InstancedCtree, GreenLabGraphsStayVersionOne) {
  CompressedTreeGraph g;
  g.set_root(g.add_record(CompressedRecord{}));
  g.compute_multiplicities();
  EXPECT_EQ(encode_ctree(g)[8], 1);
  EXPECT_THROW((void)instanced_tree_of(g), ValueError);
}

TEST(InstancedCtree, BrokenGeometryIsAParseError) {
  CompressedTreeGraph g = compress_instanced_tree(hand_tree());
  // A placed reference to a record that is not a group.
  CompressedTreeGraph bad = g;
  bad.geometry.records[3].group = false;
  EXPECT_THROW((void)decode_ctree(encode_ctree(bad)), ParseError);
  // A root that is not a group.
  bad = g;
  bad.geometry.records[0].group = false;
  EXPECT_THROW((void)decode_ctree(encode_ctree(bad)), ParseError);
  // A placement that is not a rotation.
  bad = g;
  bad.geometry.placements[0].rotation(0, 0) = 2.0;
  EXPECT_THROW((void)decode_ctree(encode_ctree(bad)), ParseError);
  // Truncated geometry, and bytes after it.
  const std::string bytes = encode_ctree(g);
  EXPECT_THROW((void)decode_ctree(bytes.substr(0, bytes.size() - 3)), ParseError);
  EXPECT_THROW((void)decode_ctree(bytes + "x"), ParseError);
  EXPECT_NO_THROW((void)decode_ctree(bytes));
}

}  // namespace
}  // namespace fspm
