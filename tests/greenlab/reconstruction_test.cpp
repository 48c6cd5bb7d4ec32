#include "greenlab/expand.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/instanced_tree.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

using testing::example;

std::size_t count_kind(const TreeGraph& t, OrganKind kind) {
  std::size_t n = 0;
  for (NodeId i = 0; i < t.size(); ++i) n += t.kind(i) == kind ? 1 : 0;
  return n;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 /
         std::numbers::pi;
}

TEST(Reconstruction, JaegerFigure1AtEveryAge) {
  const CompressedTreeGraph g = simulate_compressed(example("jaeger_figure1.toml"));
  ReconstructionStats st;
  const TreeGraph t = reconstruct(g, {}, &st);
  EXPECT_EQ(st.metamers, 6u);
  EXPECT_EQ(st.leaves, 4u);  // leaf life span 1: only the leaves of cycle 2
  EXPECT_EQ(st.flowers, 1u);
  EXPECT_EQ(st.components(), 10u);
  EXPECT_EQ(count_kind(t, OrganKind::kInternode), 6u);
  EXPECT_EQ(count_kind(t, OrganKind::kLeaf), 4u);
  EXPECT_EQ(count_kind(t, OrganKind::kFlower), 1u);
  // Trunk: two unit internodes straight up.
  EXPECT_TRUE(t.end(0).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_EQ(t.kind(1), OrganKind::kInternode);
  EXPECT_TRUE(t.end(1).isApprox(Eigen::Vector3d(0, 0, 2)));

  ReconstructionOptions young;
  young.age = 1;
  const TreeGraph t1 = reconstruct(g, young, &st);
  EXPECT_EQ(st.metamers, 2u);
  EXPECT_EQ(st.leaves, 2u);
  EXPECT_EQ(st.flowers, 0u);
  EXPECT_EQ(t1.size(), 4u);
  young.age = 3;
  EXPECT_THROW(reconstruct(g, young), ValueError);
}

TEST(Reconstruction, BranchingAngleAndSpread) {
  const CompressedTreeGraph g = simulate_compressed(example("jaeger_figure1.toml"));
  const TreeGraph t = reconstruct(g, {});
  std::vector<NodeId> lateral_bases;
  for (NodeId i = 1; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kInternode && t.order(i) == 1 && t.order(t.parent(i)) == 0) {
      lateral_bases.push_back(i);
    }
  }
  ASSERT_EQ(lateral_bases.size(), 2u);
  for (NodeId i : lateral_bases) {
    EXPECT_NEAR(angle_deg(t.direction(i), t.direction(t.parent(i))), 45.0, 1e-9);
    EXPECT_TRUE(t.start(i).isApprox(Eigen::Vector3d(0, 0, 2)));
  }
  // Two buds at one node are spread half a turn apart around the axis.
  const Eigen::Vector3d a = t.direction(lateral_bases[0]);
  const Eigen::Vector3d b = t.direction(lateral_bases[1]);
  EXPECT_NEAR(a.x() + b.x(), 0.0, 1e-9);
  EXPECT_NEAR(a.y() + b.y(), 0.0, 1e-9);
}

TEST(Reconstruction, MassartBranchesAreHorizontalRauhBranchesRise) {
  const TreeGraph massart = reconstruct(simulate_compressed(example("massart.toml")), {});
  const TreeGraph rauh = reconstruct(simulate_compressed(example("rauh.toml")), {});
  std::size_t checked = 0;
  for (NodeId i = 0; i < massart.size(); ++i) {
    if (massart.kind(i) == OrganKind::kInternode && massart.physiological_age(i) >= 2) {
      EXPECT_NEAR(massart.direction(i).z(), 0.0, 1e-9);
      ++checked;
    }
  }
  EXPECT_GT(checked, 10u);
  // Rauh: orthotropic branches turn up, so along an axis the heading's z never decreases.
  std::size_t rising = 0;
  for (NodeId i = 0; i < rauh.size(); ++i) {
    if (rauh.kind(i) != OrganKind::kInternode || rauh.physiological_age(i) != 2) continue;
    EXPECT_GT(rauh.direction(i).z(), 0.5);
    const NodeId p = rauh.parent(i);
    if (rauh.physiological_age(p) == 2) {
      EXPECT_GE(rauh.direction(i).z(), rauh.direction(p).z() - 1e-12);
      ++rising;
    }
  }
  EXPECT_GT(rising, 10u);
  // Same automaton, same counts.
  EXPECT_EQ(massart.size(), rauh.size());
}

const char* kLaw = R"([plant]
cycles = 20
[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 2 } ] } ]
internode_radius = 0.1
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

TEST(Reconstruction, QuadraticDiameterInterpolation) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(kLaw));
  ReconstructionOptions o;
  o.age = 12;
  const TreeGraph t = reconstruct(g, o);
  // Trunk metamer born at cycle 4: final radius 0.1 + 0.01 (20 - 4) = 0.26 at age 20; at age 12,
  // x = (12 - 4) / (20 - 4) = 0.5, r = 0.1 + 0.16 x^2 = 0.14 (Jaeger 3.2.2).
  bool found = false;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kInternode && t.order(i) == 0 && t.birth_time(i) == 4.0) {
      EXPECT_NEAR(t.radius(i), 0.14, 1e-12);
      found = true;
    }
  }
  EXPECT_TRUE(found);
  const TreeGraph full = reconstruct(g, {});
  EXPECT_NEAR(full.radius(3), 0.26, 1e-12);  // node 3 is the trunk metamer born at 4
}

TEST(Reconstruction, SelfPruningOfLeavesAndAxes) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(kLaw));
  ReconstructionStats st;
  reconstruct(g, {}, &st);
  // Branch born at cycle c starts growing at c + 1; it falls once c + 1 + 5 <= 20, so only
  // c = 15..19 remain: 20 trunk metamers + sum (20 - c) = 15.
  EXPECT_EQ(st.metamers, 35u);
  EXPECT_EQ(st.pruned_axes, 14u);
  // Leaves: trunk leaves of the last 3 cycles, branch leaves never fall.
  EXPECT_EQ(st.leaves, 3u + 15u);
}

TEST(Reconstruction, AnnexAllometryConservesVolumes) {
  for (double b : {0.5, 1.0, 2.0}) {
    const double vp = 3.7, vr = 1.9, href = 5.0;
    const InternodeDimensions d = internode_dimensions(vp, vr, href, b);
    EXPECT_NEAR(std::numbers::pi * d.pith_radius * d.pith_radius * d.length, vp, 1e-12);
    EXPECT_NEAR(std::numbers::pi * (d.radius * d.radius - d.pith_radius * d.pith_radius) * d.length,
                vr, 1e-12);
  }
  // At the reference volume the internode has the reference length and unit pith radius.
  const InternodeDimensions ref = internode_dimensions(std::numbers::pi * 5.0, 0.0, 5.0, 1.0);
  EXPECT_NEAR(ref.length, 5.0, 1e-12);
  EXPECT_NEAR(ref.pith_radius, 1.0, 1e-12);
}

}  // namespace
}  // namespace fspm::greenlab

namespace fspm::greenlab {
namespace {

TEST(Reconstruction, InstancedFormExpandsToTheExplicitTree) {
  // Leeuwenberg without straightening: no orientation-dependent effect, so instancing is exact.
  PlantParams p = testing::example("leeuwenberg.toml");
  p.age(1).geometry.straightening = 0.0;
  p.age(1).geometry.leaf_life_span = 2;
  const CompressedTreeGraph g = simulate_compressed(p);
  for (double age : {6.0, 4.0}) {
    ReconstructionOptions o;
    o.age = age;
    ReconstructionStats st;
    const TreeGraph explicit_tree = reconstruct(g, o, &st);
    const InstancedTree inst = reconstruct_instanced(g, o);
    EXPECT_EQ(count_instanced_tree(inst).nodes, st.components() + st.flowers);
    EXPECT_LT(inst.prototypes.size(), 10u);
    // Axis by axis, as reconstruct() numbers the nodes.
    const TreeGraph expanded =
        expand_instanced_tree(inst, explicit_tree.size(), ExpansionOrder::kAxisByAxis);
    ASSERT_EQ(expanded.size(), explicit_tree.size());
    for (NodeId n = 0; n < expanded.size(); ++n) {
      ASSERT_EQ(expanded.parent(n), explicit_tree.parent(n)) << n;
      ASSERT_EQ(expanded.kind(n), explicit_tree.kind(n)) << n;
      ASSERT_EQ(expanded.order(n), explicit_tree.order(n)) << n;
      ASSERT_TRUE(expanded.end(n).isApprox(explicit_tree.end(n), 1e-9)) << n;
      ASSERT_DOUBLE_EQ(expanded.radius(n), explicit_tree.radius(n)) << n;
    }
  }
}

}  // namespace
}  // namespace fspm::greenlab

namespace fspm::greenlab {
namespace {

TEST(Reconstruction, HugePlantsFailCleanly) {
  const PlantParams p = testing::example("jaeger_figure1.toml");
  // 2 (2^N - 1) metamers: N = 62 still fits in 64 bits, N = 64 does not.
  const CompressedTreeGraph g = simulate_compressed(p, 62);
  EXPECT_EQ(g.size(), 124u);
  EXPECT_EQ(metamers_at_age(g, 5), 62u);
  EXPECT_EQ(metamers_at_age(g, 62), g.expanded_size());
  ReconstructionOptions o;
  o.age = 40;
  EXPECT_THROW(reconstruct(g, o), ValueError);
  o.age = 8;
  ReconstructionStats st;
  reconstruct(g, o, &st);
  EXPECT_EQ(st.metamers, 510u);
  // The instanced form has no such limit: one prototype per cycle.
  o.age = 62;
  const InstancedTree inst = reconstruct_instanced(g, o);
  EXPECT_EQ(inst.prototypes.size(), 62u);
  EXPECT_THROW(simulate_compressed(p, 64), ValueError);
}

}  // namespace
}  // namespace fspm::greenlab

namespace fspm::greenlab {
namespace {

TEST(Reconstruction, Gl1VolumesGiveLengthsAndRadii) {
  const CompressedTreeGraph g = simulate_compressed(testing::example("gl1_plant.toml"));
  const TreeGraph t = reconstruct(g, {});
  // The trunk's metamers are records 0.. along the successor chain, and the tree's trunk nodes
  // come first, each followed by its leaf while the leaf lives (life span 4 of 12 cycles).
  RecordId rec = g.root();
  NodeId node = 0;
  int checked = 0;
  while (rec != kNoRecord) {
    const CompressedRecord& r = g.record(rec);
    ASSERT_EQ(t.kind(node), OrganKind::kInternode);
    ASSERT_EQ(t.order(node), 0u);
    const InternodeDimensions d = internode_dimensions(r.pith_volume, r.ring_volume, 5.0, 1.0);
    EXPECT_NEAR(t.length(node), d.length, 1e-12);
    EXPECT_NEAR(t.radius(node), d.radius, 1e-12);
    // Volume of the internode cylinder = pith + rings (density 1: volumes are masses).
    EXPECT_NEAR(std::numbers::pi * t.radius(node) * t.radius(node) * t.length(node),
                r.pith_volume + r.ring_volume, 1e-9);
    ++checked;
    NodeId next = kNoNode;
    for (NodeId c : t.children(node)) {
      if (t.kind(c) == OrganKind::kLeaf) {
        // Leaf length = sqrt(area), area = volume / thickness.
        EXPECT_NEAR(t.length(c), std::sqrt(r.leaf_volume / 0.01), 1e-12);
      } else if (t.order(c) == 0) {
        next = c;
      }
    }
    rec = r.successor;
    if (rec != kNoRecord) {
      ASSERT_NE(next, kNoNode);
      node = next;
    }
  }
  EXPECT_EQ(checked, 12);
}

}  // namespace
}  // namespace fspm::greenlab
