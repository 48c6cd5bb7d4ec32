#include "greenlab/calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fspm/error.hpp"

namespace fspm::greenlab {
namespace {

const char* kPlant = R"([plant]
cycles = 12
[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 2 } ] } ]
leaf_life_span = 4
leaf_sink = 1.0
internode_sink = 0.6
leaf_expansion = 3
internode_expansion = 3
leaf_beta_a = 2.5
leaf_beta_b = 2.0
[[age]]
index = 2
duration = 100
next_age = 0
units = [ { count = 1 } ]
leaf_life_span = 4
leaf_sink = 0.7
internode_sink = 0.3
[functional]
seed_biomass = 1.0
resistance = 0.8
projected_area = 5.0
extinction = 0.6
specific_leaf_mass = 0.05
ring_sink = 0.5
[calibration]
parameters = ["resistance", "age.1.internode_sink", "age.2.leaf_sink", "age.1.leaf_beta_a"]
)";

// Every organ mass and every production value of the true plant, with 1% multiplicative noise.
std::vector<Target> synthetic_targets(const PlantParams& truth, std::uint64_t seed) {
  std::vector<Target> t;
  for (int age = 1; age <= 2; ++age) {
    for (int c = 1; c <= truth.cycles; ++c) {
      if (age == 2 && c == 1) continue;  // no branch born in cycle 1
      t.push_back({"leaf_mass", age, c, 0.0, 0});
      t.push_back({"internode_mass", age, c, 0.0, 0});
    }
  }
  for (int c = 1; c <= truth.cycles; ++c) t.push_back({"production", 0, c, 0.0, 0});
  const std::vector<double> clean = predict_targets(truth, t);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (std::size_t i = 0; i < t.size(); ++i) t[i].value = clean[i] * (1.0 + noise(rng));
  return t;
}

TEST(Calibration, RecoversKnownParametersFromNoisyData) {
  const PlantParams truth = parse_plant_params(kPlant);
  const std::vector<Target> targets = synthetic_targets(truth, 7);
  PlantParams start = truth;
  for (const auto& n : truth.calibration_parameters) {
    set_parameter(start, n, get_parameter(truth, n) * 1.4);
  }
  const FitResult fit = fit_gl1(start, targets);
  ASSERT_TRUE(fit.converged);
  ASSERT_EQ(fit.estimates.size(), 4u);
  EXPECT_LT(fit.final_cost, fit.initial_cost);
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    const double true_value = get_parameter(truth, fit.names[i]);
    ASSERT_TRUE(std::isfinite(fit.standard_errors[i])) << fit.names[i];
    EXPECT_GT(fit.standard_errors[i], 0.0) << fit.names[i];
    // Within 4 standard errors, and the standard error itself small.
    EXPECT_NEAR(fit.estimates[i], true_value, 4.0 * fit.standard_errors[i]) << fit.names[i];
    EXPECT_LT(fit.standard_errors[i], 0.1 * true_value) << fit.names[i];
  }
  EXPECT_EQ(fit.residuals.size(), targets.size());
}

TEST(Calibration, NonConvergenceReportsFinalCost) {
  const PlantParams truth = parse_plant_params(kPlant);
  const std::vector<Target> targets = synthetic_targets(truth, 3);
  PlantParams start = truth;
  set_parameter(start, "resistance", 5.0);
  FitOptions o;
  o.max_iterations = 1;
  try {
    fit_gl1(start, targets, {}, o);
    FAIL() << "expected non-convergence";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("final cost"), std::string::npos) << e.what();
  }
}

TEST(Calibration, RefusesAnIterationLimitBelowOne) {
  const PlantParams truth = parse_plant_params(kPlant);
  FitOptions o;
  o.max_iterations = 0;
  EXPECT_THROW(fit_gl1(truth, synthetic_targets(truth, 3), {}, o), ValueError);
}

TEST(Calibration, TargetsCsv) {
  const auto t =
      parse_targets_csv("quantity,age,cycle,value\nleaf_mass,1,2,0.5\nproduction,,3,1e-2\n");
  ASSERT_EQ(t.size(), 2u);
  EXPECT_EQ(t[1].quantity, "production");
  EXPECT_EQ(t[1].cycle, 3);
  EXPECT_DOUBLE_EQ(t[1].value, 0.01);
  try {
    parse_targets_csv("quantity,age,cycle,value\nleaf_mass,1,2,abc\n", "t.csv");
    FAIL();
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 15);
  }
  EXPECT_THROW(parse_targets_csv("a,b\n", "t.csv"), ParseError);
  EXPECT_THROW(parse_targets_csv("quantity,age,cycle,value\nheight,1,2,3\n", "t.csv"), ParseError);
}

TEST(Calibration, FittedTomlRoundTrips) {
  const PlantParams truth = parse_plant_params(kPlant);
  FitResult fit;
  fit.names = {"resistance", "age.2.leaf_sink"};
  fit.estimates = {0.123, 4.5};
  const PlantParams back = parse_plant_params(fitted_toml(kPlant, fit));
  EXPECT_DOUBLE_EQ(back.functional.resistance, 0.123);
  EXPECT_DOUBLE_EQ(back.age(2).functional.leaf_sink, 4.5);
  EXPECT_DOUBLE_EQ(back.age(1).functional.leaf_sink, truth.age(1).functional.leaf_sink);
}

}  // namespace
}  // namespace fspm::greenlab
