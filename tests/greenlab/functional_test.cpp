#include "greenlab/functional.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "greenlab/simulation.hpp"

namespace fspm::greenlab {
namespace {

TEST(Functional, BetaExpansionIsNormalizedAndSymmetric) {
  const auto f = beta_expansion(5, 3.0, 3.0);
  ASSERT_EQ(f.size(), 5u);
  EXPECT_NEAR(std::accumulate(f.begin(), f.end(), 0.0), 1.0, 1e-15);
  EXPECT_NEAR(f[0], f[4], 1e-15);
  EXPECT_GT(f[2], f[1]);
  // a = b = 1: uniform.
  for (double v : beta_expansion(4, 1.0, 1.0)) EXPECT_NEAR(v, 0.25, 1e-15);
}

const char* kPlant = R"([plant]
cycles = 6
[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 2 } ] } ]
leaf_life_span = 3
leaf_sink = 1.0
internode_sink = 0.5
leaf_expansion = 2
internode_expansion = 3
leaf_beta_a = 2.0
internode_beta_b = 3.0
[[age]]
index = 2
duration = 100
next_age = 0
units = [ { count = 2 } ]
leaf_sink = 0.7
internode_sink = 0.3
[functional]
seed_biomass = 2.0
resistance = 0.5
projected_area = 4.0
extinction = 0.7
specific_leaf_mass = 0.05
ring_sink = 0.4
)";

TEST(Functional, FirstCycleByHand) {
  const PlantParams p = parse_plant_params(kPlant);
  const CompressedTreeGraph g = simulate_compressed(p);
  const Gl1Result r = run_gl1(p, organ_counts(g, 2, 6), 6);
  // Cycle 1: one metamer of age 1, no rings yet. D(1) = 1.0 f_L(0) + 0.5 f_I(0).
  const auto fl = beta_expansion(2, 2.0, 2.0);
  const auto fi = beta_expansion(3, 2.0, 3.0);
  const double d1 = 1.0 * fl[0] + 0.5 * fi[0];
  EXPECT_NEAR(r.demand[1], d1, 1e-12);
  const double leaf1 = 1.0 * fl[0] * 2.0 / d1;
  const double s1 = leaf1 / 0.05;
  EXPECT_NEAR(r.leaf_area[1], s1, 1e-12);
  EXPECT_NEAR(r.production[1], 1.0 * (4.0 / 0.5) * (1 - std::exp(-0.7 * s1 / 4.0)), 1e-12);
}

TEST(Functional, AllocatedBiomassIsConserved) {
  const PlantParams p = parse_plant_params(kPlant);
  const CompressedTreeGraph g = simulate_compressed(p);
  const auto counts = organ_counts(g, 2, 6);
  const Gl1Result r = run_gl1(p, counts, 6);
  // Every cycle has demand, so all that was produced before the last cycle sits in organs
  // (masses at the end include expansion still to come only through later cycles).
  double produced = 0.0;
  for (int n = 1; n <= 6; ++n) produced += r.production[static_cast<std::size_t>(n - 1)];
  double in_organs = 0.0;
  double internodes = 0.0;
  for (int a = 1; a <= 2; ++a) {
    for (int c = 1; c <= 6; ++c) {
      const double k = counts[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)];
      in_organs += k * (r.leaf_mass[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)] +
                        r.internode_mass[static_cast<std::size_t>(a)][static_cast<std::size_t>(c)] +
                        r.ring_mass[static_cast<std::size_t>(c)]);
      internodes += k;
    }
  }
  EXPECT_GT(internodes, 6.0);
  EXPECT_NEAR(in_organs, produced, 1e-9 * produced);
}

TEST(Functional, VolumesStoredInGraph) {
  const PlantParams p = parse_plant_params(kPlant);
  const CompressedTreeGraph g = simulate_compressed(p);
  const Gl1Result r = run_gl1(p, organ_counts(g, 2, 6), 6);
  for (const auto& rec : g.records()) {
    const auto c = static_cast<std::size_t>(rec.birth);
    EXPECT_DOUBLE_EQ(rec.leaf_volume, r.leaf_mass[rec.physiological_age][c]);  // density 1
    EXPECT_DOUBLE_EQ(rec.ring_volume, r.ring_mass[c]);
    EXPECT_GT(rec.pith_volume, 0.0);
  }
}

}  // namespace
}  // namespace fspm::greenlab
