#include "greenlab/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "greenlab/explicit_simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

using testing::example;
using testing::two_age_plant;

TEST(Simulation, JaegerFigure1Has6MetamersAnd4Records) {
  const PlantParams p = example("jaeger_figure1.toml");
  std::mt19937_64 rng(1);
  const ExplicitPlant explicit_plant = simulate_explicit(p, rng);
  EXPECT_EQ(explicit_plant.metamers.size(), 6u);
  const CompressedTreeGraph g = simulate_compressed(p);
  ASSERT_EQ(g.size(), 4u);
  // Jaeger 2.2.2, compressed table: 0 -> 1; 1 bears {2, 2}; 2 -> 3; 3 ends.
  EXPECT_EQ(g.record(0).successor, 1u);
  EXPECT_EQ(g.record(1).successor, kNoRecord);
  ASSERT_EQ(g.axillaries(1).size(), 2u);
  EXPECT_EQ(g.axillaries(1)[0], 2u);
  EXPECT_EQ(g.axillaries(1)[1], 2u);
  EXPECT_EQ(g.record(2).successor, 3u);
  EXPECT_EQ(g.record(3).successor, kNoRecord);
  EXPECT_TRUE(g.axillaries(3).empty());
  EXPECT_EQ(g.record(1).apex, ApexState::kFlower);  // the trunk apex became F
  EXPECT_EQ(g.record(3).apex, ApexState::kBud);     // the lateral apices are still B0
  EXPECT_EQ(g.record(2).multiplicity, 2u);
  EXPECT_EQ(g.expanded_size(), 6u);
  EXPECT_EQ(canonical_sequence(g), canonical_sequence(explicit_plant));
}

TEST(Simulation, BinaryTreeClosedForm) {
  // Each growth unit of 2 metamers gives two units the next cycle: 2 (2^N - 1) metamers, and
  // one substructure of 2 records per cycle.
  PlantParams p = example("jaeger_figure1.toml");
  for (int n : {1, 3, 10, 30}) {
    const CompressedTreeGraph g = simulate_compressed(p, n);
    EXPECT_EQ(g.expanded_size(), 2 * ((std::uint64_t{1} << n) - 1)) << n;
    EXPECT_EQ(g.size(), static_cast<std::size_t>(2 * n)) << n;
  }
}

TEST(Simulation, TwoAgeClosedFormAndLinearCost) {
  // Trunk: 1 metamer per cycle with one age-2 bud; the branch born at c grows N - c metamers.
  const int n = 40;
  const PlantParams p = parse_plant_params(two_age_plant(n, 1, 1, 1.0, 1.0, 1.0));
  const CompressedTreeGraph g = simulate_compressed(p);
  const OrganCounts counts = count_organs(g);
  EXPECT_EQ(counts.metamers_by_age.at(1), static_cast<std::uint64_t>(n));
  EXPECT_EQ(counts.metamers_by_age.at(2), static_cast<std::uint64_t>(n * (n - 1) / 2));
  // Cost grows with cycles x ages: one record per (age, cycle).
  EXPECT_LE(g.size(), static_cast<std::size_t>(2 * n));
}

// Deterministic plants: the expansion of the compressed graph is exactly the explicit tree.
TEST(Simulation, DeterministicExpansionEqualsExplicitTree) {
  std::vector<std::pair<std::string, PlantParams>> plants;
  for (const char* name :
       {"jaeger_figure1.toml", "leeuwenberg.toml", "rauh.toml", "massart.toml"}) {
    plants.emplace_back(name, example(name));
  }
  // Several ages, transitions to the same and to higher ages, a sylleptic (delay 0) bud of a
  // higher age, delays > 1, an empty run and a terminal without flower.
  plants.emplace_back("mixed", parse_plant_params(R"([plant]
cycles = 9
[[age]]
index = 1
duration = 2
next_age = 1
units = [ { count = 1, axillary = [ { age = 2, count = 1 }, { age = 3, count = 2 } ] }, { count = 0 } ]
[[age]]
index = 2
duration = 3
next_age = 3
branching_delay = 0
units = [ { count = 2, axillary = [ { age = 3, count = 1 } ] } ]
[[age]]
index = 3
duration = 2
next_age = 0
terminal = "none"
branching_delay = 2
units = [ { count = 1 } ]
)"));
  for (const auto& [name, p] : plants) {
    std::mt19937_64 rng(1);
    const ExplicitPlant e = simulate_explicit(p, rng);
    const CompressedTreeGraph g = simulate_compressed(p);
    EXPECT_EQ(g.expanded_size(), e.metamers.size()) << name;
    EXPECT_EQ(canonical_sequence(g), canonical_sequence(e)) << name;
    EXPECT_EQ(g.expand().size(), e.metamers.size()) << name;
    EXPECT_LT(g.size(), e.metamers.size() + 1) << name;
  }
}

// Mean, variance and fourth central moment of a discrete distribution.
struct Moments {
  double mean = 0, var = 0, mu4 = 0;
};
Moments moments(const std::map<long, double>& pmf) {
  Moments m;
  for (const auto& [x, p] : pmf) m.mean += p * static_cast<double>(x);
  for (const auto& [x, p] : pmf) {
    const double d = static_cast<double>(x) - m.mean;
    m.var += p * d * d;
    m.mu4 += p * d * d * d * d;
  }
  return m;
}
// Distribution of a sum of independent variables.
std::map<long, double> convolve(const std::map<long, double>& a, const std::map<long, double>& b) {
  std::map<long, double> out;
  for (const auto& [x, p] : a) {
    for (const auto& [y, q] : b) out[x + y] += p * q;
  }
  return out;
}
std::map<long, double> scaled_bernoulli(long value, double p) {
  if (value == 0) return {{0, 1.0}};
  return {{0, 1 - p}, {value, p}};
}

// Sample mean and variance of metamer counts over `runs` seeds, against theory within 4.5
// standard errors (the variance's from the fourth moment).
void expect_matches(const PlantParams& p, const Moments& theory, const char* what) {
  const int runs = 3000;
  for (int sim = 0; sim < 2; ++sim) {
    double sum = 0, sum2 = 0;
    for (int seed = 0; seed < runs; ++seed) {
      std::mt19937_64 rng(static_cast<std::uint64_t>(seed) * 7919 + 17);
      double x = 0;
      if (sim == 0) {
        x = static_cast<double>(simulate_compressed(p, rng).expanded_size());
      } else {
        x = static_cast<double>(simulate_explicit(p, rng).metamers.size());
      }
      sum += x;
      sum2 += x * x;
    }
    const double mean = sum / runs;
    const double var = (sum2 - runs * mean * mean) / (runs - 1);
    const double se_mean = std::sqrt(theory.var / runs);
    const double se_var =
        std::sqrt((theory.mu4 - theory.var * theory.var * (runs - 3.0) / (runs - 1.0)) / runs);
    const char* which = sim == 0 ? "compressed" : "explicit";
    EXPECT_NEAR(mean, theory.mean, 4.5 * se_mean) << what << " " << which;
    EXPECT_NEAR(var, theory.var, 4.5 * se_var) << what << " " << which;
  }
}

TEST(Simulation, Gl2GrowthProbabilityIsBinomial) {
  // 2 metamers per unit, no branching: 2 Bin(N, g).
  const int n = 20;
  const double g = 0.6;
  const PlantParams p = parse_plant_params(two_age_plant(n, 2, 0, 1.0, g, 1.0));
  std::map<long, double> pmf{{0, 1.0}};
  for (int c = 0; c < n; ++c) pmf = convolve(pmf, scaled_bernoulli(2, g));
  expect_matches(p, moments(pmf), "growth");
}

TEST(Simulation, Gl2SurvivalIsTruncatedGeometric) {
  // Units grown before the apex dies: P(K = k) = s^k (1 - s) for k < N, P(K = N) = s^N.
  const int n = 20;
  const double s = 0.9;
  const PlantParams p = parse_plant_params(two_age_plant(n, 3, 0, 1.0, 1.0, s));
  std::map<long, double> pmf;
  for (int k = 0; k < n; ++k) pmf[3 * k] = std::pow(s, k) * (1 - s);
  pmf[3 * n] = std::pow(s, n);
  expect_matches(p, moments(pmf), "survival");
}

TEST(Simulation, Gl2BranchingProbabilityIsSumOfBernoullis) {
  // Trunk of N metamers; the bud born at cycle c branches with probability b into N - c metamers.
  const int n = 20;
  const double b = 0.3;
  const PlantParams p = parse_plant_params(two_age_plant(n, 1, 1, b, 1.0, 1.0));
  std::map<long, double> pmf{{n, 1.0}};
  for (int c = 1; c <= n; ++c) pmf = convolve(pmf, scaled_bernoulli(n - c, b));
  expect_matches(p, moments(pmf), "branching");
}

TEST(Simulation, SameSeedSameResult) {
  const PlantParams p = parse_plant_params(two_age_plant(15, 2, 2, 0.5, 0.8, 0.95));
  std::mt19937_64 a(42), b(42), c(43);
  const CompressedTreeGraph ga = simulate_compressed(p, a);
  EXPECT_TRUE(ga == simulate_compressed(p, b));
  EXPECT_FALSE(ga == simulate_compressed(p, c));
}

TEST(Simulation, LivingLeavesFollowLifeSpan) {
  // Binary tree, leaf life span 1: only the 2^(N-1) units of the last cycle carry leaves.
  const PlantParams p = example("jaeger_figure1.toml");
  const CompressedTreeGraph g = simulate_compressed(p, 6);
  const OrganCounts c = count_organs(g);
  EXPECT_EQ(c.metamers, 126u);
  EXPECT_EQ(c.leaves, 64u);
  EXPECT_EQ(c.flowers, 31u);  // every unit but the last cycle's ended in a flower
  EXPECT_EQ(c.buds, 32u);
}

}  // namespace
}  // namespace fspm::greenlab
