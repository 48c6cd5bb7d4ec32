// Continuous birth dates: the metamers of a growth unit appear one after another through their
// cycle (metamer k of n grown in cycle c born at c - 1 + k/n), checked against dates and counts
// worked out by hand and against the explicit simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fspm/error.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/explicit_simulation.hpp"
#include "greenlab/functional.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

// A trunk of 3 metamers per cycle (2, then one bearing a bud of age 2); age 2 grows one metamer
// per cycle from the cycle after its bud.
std::string trunk_plant(const std::string& birth_dates) {
  return "[plant]\ncycles = 2\nbirth_dates = \"" + birth_dates +
         "\"\n[[age]]\nindex = 1\nduration = 100\nnext_age = 0\n"
         "units = [ { count = 2 }, { count = 1, axillary = [ { age = 2 } ] } ]\n"
         "leaf_life_span = 1\ninternode_radius = 0.05\nradius_growth = 0.03\n"
         "[[age]]\nindex = 2\nduration = 100\nnext_age = 0\nunits = [ { count = 1 } ]\n";
}

TEST(ContinuousBirths, DatesAndCyclesAtChosenPoints) {
  EXPECT_DOUBLE_EQ(metamer_birth(BirthDates::kCycle, 2, 1, 3), 2.0);
  EXPECT_DOUBLE_EQ(metamer_birth(BirthDates::kContinuous, 2, 1, 3), 1.0 + 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(metamer_birth(BirthDates::kContinuous, 2, 2, 3), 1.0 + 2.0 / 3.0);
  EXPECT_EQ(metamer_birth(BirthDates::kContinuous, 2, 3, 3), 2.0);  // the unit ends with its cycle
  EXPECT_EQ(birth_cycle(1.0 + 1.0 / 3.0), 2);
  EXPECT_EQ(birth_cycle(2.0), 2);
  EXPECT_EQ(birth_cycle(2.5), 3);
}

TEST(ContinuousBirths, TheSimulationProducesFractionalDates) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(trunk_plant("continuous")));
  // The trunk, record after record from the root: 1/3, 2/3, 1, 4/3, 5/3, 2.
  std::vector<double> trunk;
  for (RecordId id = g.root(); id != kNoRecord; id = g.record(id).successor) {
    trunk.push_back(g.record(id).birth);
  }
  const std::vector<double> expected{1.0 / 3, 2.0 / 3, 1.0, 4.0 / 3, 5.0 / 3, 2.0};
  ASSERT_EQ(trunk.size(), expected.size());
  for (std::size_t i = 0; i < trunk.size(); ++i) EXPECT_DOUBLE_EQ(trunk[i], expected[i]) << i;
  // The bud of cycle 1 grows its single metamer in cycle 2: born at 2 - 1 + 1/1 = 2 (the bud of
  // cycle 2 would grow in cycle 3, after the simulation).
  std::vector<double> laterals;
  for (const RecordId a : g.axillary_refs()) laterals.push_back(g.record(a).birth);
  ASSERT_EQ(laterals.size(), 1u);
  EXPECT_EQ(laterals[0], 2.0);
  // Cycle births for comparison: 1, 1, 1, 2, 2, 2.
  const CompressedTreeGraph c = simulate_compressed(parse_plant_params(trunk_plant("cycle")));
  EXPECT_EQ(c.record(c.root()).birth, 1.0);
}

TEST(ContinuousBirths, ReconstructionBetweenCyclesShowsPartOfAUnit) {
  const CompressedTreeGraph g = simulate_compressed(parse_plant_params(trunk_plant("continuous")));
  ReconstructionOptions o;
  o.age = 1.5;
  ReconstructionStats st;
  const TreeGraph t = reconstruct(g, o, &st);
  // Born by 1.5: 1/3, 2/3, 1, 4/3. Leaves living one cycle: birth + 1 > 1.5 for 2/3, 1, 4/3.
  EXPECT_EQ(st.metamers, 4u);
  EXPECT_EQ(st.leaves, 3u);
  // With cycle births the same age shows the whole first unit and all its leaves.
  const CompressedTreeGraph c = simulate_compressed(parse_plant_params(trunk_plant("cycle")));
  (void)reconstruct(c, o, &st);
  EXPECT_EQ(st.metamers, 3u);
  EXPECT_EQ(st.leaves, 3u);
  // At whole ages both show the same metamers.
  for (double age : {1.0, 2.0}) {
    o.age = age;
    ReconstructionStats a, b;
    (void)reconstruct(g, o, &a);
    (void)reconstruct(c, o, &b);
    EXPECT_EQ(a.metamers, b.metamers) << age;
  }
  // Radius at the final age 2 of the first metamer (born 1/3): 0.05 + 0.03 (2 - 1/3) = 0.1.
  const TreeGraph full = reconstruct(g, {});
  EXPECT_NEAR(full.radius(0), 0.1, 1e-12);
  EXPECT_NEAR(full.birth_time(0), 1.0 / 3.0, 1e-15);
}

TEST(ContinuousBirths, CompressedMatchesExplicitOnEveryExample) {
  for (const char* name :
       {"jaeger_figure1.toml", "leeuwenberg.toml", "rauh.toml", "massart.toml", "gl1_plant.toml"}) {
    PlantParams p = testing::example(name);
    p.birth_dates = BirthDates::kContinuous;
    std::mt19937_64 rng(p.seed);
    const auto expected = canonical_sequence(simulate_explicit(p, rng));
    const auto got = canonical_sequence(simulate_compressed(p));
    EXPECT_EQ(got, expected) << name;
    std::size_t fractional = 0;
    for (const auto& m : got) fractional += m.birth != std::floor(m.birth) ? 1 : 0;
    // gl1_plant.toml grows one metamer per unit: its dates stay whole.
    if (std::string(name) != "gl1_plant.toml") {
      EXPECT_GT(fractional, 0u) << name;
    }
  }
}

TEST(ContinuousBirths, Gl1FunctioningStaysPerCycle) {
  // GL1 shares biomass per cycle: a metamer born at 4/3 is an organ of cycle 2 as with cycle
  // births, so production and every record's volumes are the same in both modes.
  PlantParams p = testing::example("gl1_plant.toml");
  p.age(2).units[0].count = 3;  // units of several metamers, so that some dates are fractional
  const CompressedTreeGraph c = simulate_compressed(p);
  p.birth_dates = BirthDates::kContinuous;
  const CompressedTreeGraph g = simulate_compressed(p);
  ASSERT_EQ(g.size(), c.size());
  const int cycles = static_cast<int>(g.final_age);
  const auto n_ages = static_cast<int>(p.ages.size());
  EXPECT_EQ(organ_counts(g, n_ages, cycles), organ_counts(c, n_ages, cycles));
  std::size_t fractional = 0;
  for (RecordId id = 0; id < g.size(); ++id) {
    EXPECT_EQ(birth_cycle(g.record(id).birth), static_cast<long>(c.record(id).birth));
    EXPECT_EQ(g.record(id).pith_volume, c.record(id).pith_volume);
    EXPECT_EQ(g.record(id).leaf_volume, c.record(id).leaf_volume);
    EXPECT_EQ(g.record(id).ring_volume, c.record(id).ring_volume);
    fractional += g.record(id).birth != c.record(id).birth ? 1 : 0;
  }
  EXPECT_GT(fractional, 0u);
}

TEST(ContinuousBirths, UnknownModeIsRefused) {
  EXPECT_THROW(parse_plant_params(trunk_plant("daily")), ParseError);
}

}  // namespace
}  // namespace fspm::greenlab
