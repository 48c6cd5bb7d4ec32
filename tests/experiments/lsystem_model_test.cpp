#include "experiments/lsystem_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "experiments/model_factory.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

TEST(LSystemModel, DefinesAndStepsReachTheGrammar) {
  const auto dir = testing::scratch("lsys");
  const std::string file = testing::write(dir / "line.l", testing::kLineLSystem);
  const auto model = make_lsystem_model(file, "", true);
  // n steps of A --> F(L)A: n internodes of length L straight up.
  const RunResult r = model->run({{"steps", std::int64_t{4}}, {"define.L", 0.5}}, 1, RunContext{});
  EXPECT_EQ(r.metrics.at("internodes"), 4);
  EXPECT_DOUBLE_EQ(r.metrics.at("height"), 2.0);
  EXPECT_DOUBLE_EQ(r.metrics.at("total_length"), 2.0);
  ASSERT_TRUE(r.tree.has_value());
  EXPECT_EQ(r.tree->size(), 4u);
  // The file's derivation length (3) and #define (2) without overrides.
  const RunResult d = model->run({}, 1, RunContext{});
  EXPECT_DOUBLE_EQ(d.metrics.at("height"), 6.0);
}

TEST(LSystemModel, BracketedSystemHasFivePowerNInternodes) {
  // ABOP fig. 1.24a: F --> F[+F]F[-F]F multiplies the F count by 5 per step.
  const std::string file = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/abop_1_24a.l";
  const auto model = make_lsystem_model(file, "", false);
  for (std::int64_t n = 1; n <= 4; ++n) {
    const RunResult r = model->run({{"steps", n}}, 1, RunContext{});
    EXPECT_EQ(r.metrics.at("internodes"), std::pow(5.0, static_cast<double>(n)));
  }
}

TEST(LSystemModel, UnknownParametersAreRejected) {
  const auto dir = testing::scratch("lsys_bad");
  testing::write(dir / "line.l", testing::kLineLSystem);
  const std::string exp = testing::write(
      dir / "e.toml",
      "[experiment]\nname = \"x\"\n[model]\nkind = \"lsystem\"\nfile = \"line.l\"\n[sweep]\n"
      "steps = [1, 2]\nangle = [3]\n");
  const Experiment x = read_experiment(exp);
  const auto model = make_model(x);
  try {
    check_experiment(x, *model, RunPlan(x));
    FAIL();
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 8);
    EXPECT_NE(std::string(e.what()).find("angle"), std::string::npos);
  }
}

TEST(LSystemModel, ATimeLimitStopsTheDerivation) {
  const std::string file = std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/abop_1_24a.l";
  const auto model = make_lsystem_model(file, "", false);
  const RunContext expired(RunContext::Clock::now() - std::chrono::seconds(1), nullptr);
  try {
    model->run({{"steps", std::int64_t{8}}}, 1, expired);
    FAIL();
  } catch (const RunStopped& e) {
    EXPECT_TRUE(e.timed_out());
  }
}

}  // namespace
}  // namespace fspm::experiments
