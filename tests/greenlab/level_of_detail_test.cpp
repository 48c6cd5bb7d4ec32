// Level of detail by exploring the graph (Jaeger 3.1.1) and the line tree sizes of Jaeger's
// Table 1, on plants small enough to count by hand.
#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "fspm/line_tree.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

using testing::example;

ReconstructionOptions at(double age, double max_order, bool merge) {
  ReconstructionOptions o;
  o.age = age;
  o.lod.max_order = max_order;
  o.lod.merge_collinear = merge;
  return o;
}

std::size_t count_kind(const TreeGraph& t, OrganKind kind) {
  std::size_t n = 0;
  for (NodeId i = 0; i < t.size(); ++i) n += t.kind(i) == kind ? 1 : 0;
  return n;
}

// Jaeger's Figure 1 plant: cycle 1 grows a trunk of 2 metamers whose top bears 2 buds and a
// flower; cycle 2 grows each bud into a branch of 2 metamers. Leaves live one cycle and count as
// order 1 on the trunk, 2 on the branches. At age 2: 6 internodes, 4 leaves (the branches'),
// 1 flower (the trunk's; the branches' show from cycle 3).
TEST(LevelOfDetail, JaegerFigure1ByHand) {
  const CompressedTreeGraph g = simulate_compressed(example("jaeger_figure1.toml"));
  const double all = LevelOfDetail::kUnlimitedOrder;
  EXPECT_EQ(reconstruct(g, at(2, all, false)).size(), 11u);
  // Order 0: the trunk and its flower; merged, the trunk's 2 internodes become one (its first
  // leaf has fallen, the branches are cut).
  EXPECT_EQ(reconstruct(g, at(2, 0, false)).size(), 3u);
  const TreeGraph trunk = reconstruct(g, at(2, 0, true));
  ASSERT_EQ(trunk.size(), 2u);
  EXPECT_DOUBLE_EQ(trunk.length(0), 2.0);
  EXPECT_EQ(trunk.kind(1), OrganKind::kFlower);
  // Order 1, merged: trunk 1 + flower 1 + 2 bare branches of one merged internode each.
  ReconstructionStats st;
  const TreeGraph one = reconstruct(g, at(2, 1, true), &st);
  EXPECT_EQ(one.size(), 4u);
  EXPECT_EQ(st.metamers, 3u);  // internodes written
  EXPECT_EQ(st.flowers, 1u);
  // Order 2, merged: the branch leaves are back; the one at the top of each branch's first
  // metamer stops the merge there: trunk 1 + flower 1 + 2 x (2 internodes + 2 leaves).
  const TreeGraph two = reconstruct(g, at(2, 2, true));
  EXPECT_EQ(two.size(), 10u);
  EXPECT_EQ(count_kind(two, OrganKind::kLeaf), 4u);
  // Age 1: the trunk with its 2 living leaves; order 0 merged leaves one internode.
  EXPECT_EQ(reconstruct(g, at(1, all, true)).size(), 4u);
  EXPECT_EQ(reconstruct(g, at(1, 0, true)).size(), 1u);
  // The memory estimate counts the order limit: 2 trunk metamers, then the 4 of the branches.
  EXPECT_EQ(metamers_within_order(g, 2, 0), 2u);
  EXPECT_EQ(metamers_within_order(g, 2, 1), 6u);
  EXPECT_EQ(metamers_within_order(g, 1, 1), 2u);
  EXPECT_EQ(metamers_within_order(g, 2, all), 6u);
}

TEST(LevelOfDetail, LineTreeRefusesIt) {
  const CompressedTreeGraph g = simulate_compressed(example("jaeger_figure1.toml"));
  EXPECT_THROW(reconstruct_lines(g, at(2, 0, true)), ValueError);
}

// Jaeger's Table 1 "sequence size": the line trees of ages 1..final. By hand (above): age 1 has
// 2 internodes and 2 leaves, age 2 has 6 internodes, 4 leaves and 1 flower.
TEST(LineTreeSizes, JaegerFigure1ByHand) {
  const CompressedTreeGraph g = simulate_compressed(example("jaeger_figure1.toml"));
  ReconstructionOptions o;
  o.age = 1;
  EXPECT_EQ(line_records_at_age(g, o), 4u);
  o.age = 2;
  EXPECT_EQ(line_records_at_age(g, o), 11u);
  o.leaves = false;
  EXPECT_EQ(line_records_at_age(g, o), 7u);
  EXPECT_EQ(LineTree::kBytesPerRecord * (4 + 11), 675u);
}

// Axes fall: a trunk of one metamer per cycle bearing an age-2 bud each, which grows one metamer
// per cycle from the next cycle and lives 5 cycles; trunk leaves live 3 cycles, branch leaves
// never fall. At age 20 the branches born at cycles 15..19 remain, with 5 + 4 + 3 + 2 + 1 = 15
// metamers: 20 + 15 internodes, 3 + 15 leaves, no flower.
const char* kFallingAxes = R"([plant]
cycles = 20
[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 2 } ] } ]
radius_growth = 0.01
leaf_life_span = 3
[[age]]
index = 2
duration = 100
next_age = 0
units = [ { count = 1 } ]
axis_life_span = 5
leaf_life_span = 0
)";

TEST(LineTreeSizes, FallenAxesByHand) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(kFallingAxes));
  EXPECT_EQ(line_records_at_age(g, {}), 35u + 18u);
  // Order 0 merged: the trunk's 20 metamers (of growing radii) in one straight internode.
  const TreeGraph trunk = reconstruct(g, at(-1, 0, true));
  ASSERT_EQ(trunk.size(), 1u);
  EXPECT_DOUBLE_EQ(trunk.length(0), 20.0);
}

// The count on the graph agrees with the line trees written, at every age of every example.
TEST(LineTreeSizes, MatchTheReconstructionOnEveryExample) {
  for (const char* name :
       {"jaeger_figure1.toml", "leeuwenberg.toml", "rauh.toml", "massart.toml", "gl1_plant.toml"}) {
    const CompressedTreeGraph g = simulate_compressed(example(name));
    for (int age = 1; age <= static_cast<int>(g.final_age); ++age) {
      ReconstructionOptions o;
      o.age = age;
      EXPECT_EQ(line_records_at_age(g, o), reconstruct_lines(g, o).size()) << name << " " << age;
    }
  }
}

}  // namespace
}  // namespace fspm::greenlab
