#include "experiments/greenlab_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_files.hpp"

namespace fspm::experiments {
namespace {

// One physiological age making one metamer per cycle, no laterals: after N cycles a straight
// trunk of N internodes of 0.5 m.
constexpr const char* kTrunk = R"(
[plant]
cycles = 3
seed = 1

[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1 } ]
internode_length = 0.5
leaf_length = 0.0  # leaves add no height
)";

TEST(GreenLabModel, CyclesAndParametersReachTheSimulation) {
  const auto dir = testing::scratch("greenlab");
  const auto model = make_greenlab_model(testing::write(dir / "trunk.toml", kTrunk));
  const RunResult r = model->run({{"cycles", std::int64_t{5}}}, 1, RunContext{});
  EXPECT_EQ(r.metrics.at("internodes"), 5);
  EXPECT_NEAR(r.metrics.at("height"), 2.5, 1e-9);
  EXPECT_NEAR(r.metrics.at("total_length"), 2.5, 1e-9);
  EXPECT_TRUE(std::isnan(r.metrics.at("biomass")));  // no GL1 in this description
  EXPECT_NO_THROW(model->check_parameter("cycles", std::int64_t{4}));
  EXPECT_THROW(model->check_parameter("cycles", std::int64_t{0}), ValueError);
  EXPECT_THROW(model->check_parameter("no_such_parameter", 1.0), ValueError);
}

}  // namespace
}  // namespace fspm::experiments
