// The species library (Pirk sec. 3.4, Figure 3.5): a hand-built branchlet cut into patches with
// docking points worked out by hand, and the L-system library's invariants.
#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "scan_decoding/species_library.hpp"

namespace fspm::scan_decoding {
namespace {

// Trunk of three internodes up z (radius 0.1) from (1, 2, 3); a lateral of two internodes (order
// 1, radius 0.05) leaving the second along +x; a leaf on the first and on the lateral's tip.
TreeGraph hand_branchlet() {
  TreeGraph t;
  const Eigen::Vector3d o(1, 2, 3);
  NodeData d;
  d.radius = 0.1;
  d.start = o, d.end = o + Eigen::Vector3d(0, 0, 1);
  t.add_node(kNoNode, d);  // 0
  NodeData leaf;
  leaf.kind = OrganKind::kLeaf;
  leaf.order = 1;
  leaf.start = o + Eigen::Vector3d(0, 0, 0.5), leaf.end = o + Eigen::Vector3d(0.2, 0, 0.5);
  t.add_node(0, leaf);  // 1
  d.start = o + Eigen::Vector3d(0, 0, 1), d.end = o + Eigen::Vector3d(0, 0, 2);
  t.add_node(0, d);  // 2
  NodeData lateral;
  lateral.order = 1;
  lateral.radius = 0.05;
  lateral.start = o + Eigen::Vector3d(0, 0, 2), lateral.end = o + Eigen::Vector3d(1, 0, 2);
  t.add_node(2, lateral);  // 3
  d.start = o + Eigen::Vector3d(0, 0, 2), d.end = o + Eigen::Vector3d(0, 0, 3);
  t.add_node(2, d);  // 4
  lateral.start = o + Eigen::Vector3d(1, 0, 2), lateral.end = o + Eigen::Vector3d(2, 0, 2.5);
  t.add_node(3, lateral);  // 5
  leaf.order = 2;
  leaf.start = lateral.end, leaf.end = lateral.end + Eigen::Vector3d(0, 0.3, 0);
  t.add_node(5, leaf);  // 6
  return t;
}

TEST(SpeciesLibrary, CutsOnePatchPerAxisWithDockingPoints) {
  const std::vector<Patch> patches = cut_into_patches(hand_branchlet(), 7);
  ASSERT_EQ(patches.size(), 2u);
  const Patch& trunk = patches[0];
  EXPECT_EQ(trunk.branchlet, 7u);
  EXPECT_EQ(trunk.geometry.size(), 4u);  // three internodes and a leaf
  EXPECT_EQ(trunk.leaves, 1u);
  EXPECT_DOUBLE_EQ(trunk.thickness, 1.0);
  EXPECT_TRUE(trunk.direction.isApprox(Eigen::Vector3d::UnitZ()));
  EXPECT_DOUBLE_EQ(trunk.length_m, 3.0);
  EXPECT_TRUE(trunk.geometry.start(0).isZero());  // moved to the origin
  ASSERT_EQ(trunk.dockings.size(), 1u);
  const DockingPoint& dock = trunk.dockings[0];
  EXPECT_TRUE(dock.position.isApprox(Eigen::Vector3d(0, 0, 2)));
  EXPECT_TRUE(dock.direction.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_DOUBLE_EQ(dock.thickness, 0.5);
  EXPECT_TRUE(trunk.geometry.end(dock.node).isApprox(Eigen::Vector3d(0, 0, 2)));
  const Patch& side = patches[1];
  EXPECT_EQ(side.geometry.size(), 3u);
  EXPECT_EQ(side.leaves, 1u);
  EXPECT_DOUBLE_EQ(side.thickness, 0.5);
  EXPECT_TRUE(side.dockings.empty());
  EXPECT_TRUE(side.direction.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(side.length_m, 2.0, 1e-12);  // the second internode ends 2 along +x
}

TEST(SpeciesLibrary, LSystemBranchletsGiveGradedPatches) {
  const SpeciesLibrary lib = make_species_library("willow", {4, 5, 3});
  ASSERT_GT(lib.patches.size(), 4u);
  std::size_t trunks = 0, terminal = 0, leaves = 0;
  for (const Patch& p : lib.patches) {
    EXPECT_GT(p.thickness, 0.0);
    EXPECT_LE(p.thickness, 1.0 + 1e-12);
    EXPECT_GT(p.length_m, 0.0);
    trunks += p.thickness > 1.0 - 1e-12;
    terminal += p.dockings.empty();
    leaves += p.leaves;
    for (const DockingPoint& d : p.dockings) EXPECT_LT(d.thickness, p.thickness);
  }
  EXPECT_EQ(trunks, 4u);  // one main axis per branchlet
  EXPECT_GT(terminal, 0u);
  EXPECT_GT(leaves, 0u);
}

TEST(SpeciesLibrary, SeededAndChecked) {
  const SpeciesLibrary a = make_species_library("pine", {2, 4, 9});
  const SpeciesLibrary b = make_species_library("pine", {2, 4, 9});
  ASSERT_EQ(a.patches.size(), b.patches.size());
  for (std::size_t k = 0; k < a.patches.size(); ++k) {
    ASSERT_EQ(a.patches[k].geometry.size(), b.patches[k].geometry.size());
    EXPECT_EQ(a.patches[k].geometry.end(0), b.patches[k].geometry.end(0));
  }
  EXPECT_THROW(make_species_library("pinus"), ValueError);
  EXPECT_THROW(make_species_library("pine", {0, 4, 1}), ValueError);
  EXPECT_THROW(cut_into_patches(TreeGraph{}, 0), ValueError);
}

}  // namespace
}  // namespace fspm::scan_decoding
