#include "experiments/run_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "experiments/run_seed.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::experiments {
namespace {

Experiment parse(const std::string& body) {
  return parse_experiment(
      "[experiment]\nname = \"t\"\nseed = 0\n[model]\nkind = \"synthetic\"\n" + body, "t.toml");
}

TEST(RunSeed, IsSplitMix64OfTheExperimentSeed) {
  // Reference outputs of Vigna's splitmix64.c seeded with 0 (also the first words that
  // xoshiro256 seeding draws): 0xe220a8397b1dcdaf, 0x6e789e6aa1b965f4, 0x06c45d188009454f.
  EXPECT_EQ(run_seed(0, 0), 0xe220a8397b1dcdafULL >> 1);
  EXPECT_EQ(run_seed(0, 1), 0x6e789e6aa1b965f4ULL >> 1);
  EXPECT_EQ(run_seed(0, 2), 0x06c45d188009454fULL >> 1);
  EXPECT_NE(run_seed(1, 0), run_seed(0, 0));
}

TEST(RunPlan, LastAxisVariesFastestThenReplicates) {
  const Experiment y = parse_experiment(
      "[experiment]\nname = \"t\"\nseed = 7\nreplicates = 2\n[model]\nkind = \"synthetic\"\n"
      "[parameters]\nnodes = 3\n[sweep]\n\"x.a\" = [1, 2]\n\"x.b\" = [10, 20, 30]\n",
      "t.toml");
  const RunPlan plan(y);
  ASSERT_EQ(plan.size(), 12u);
  ASSERT_EQ(plan.points(), 6u);
  const RunSpec r = plan.run(7);  // point 3 = (a index 1, b index 0), replicate 1
  EXPECT_EQ(r.point, 3u);
  EXPECT_EQ(r.replicate, 1u);
  EXPECT_EQ(std::get<std::int64_t>(r.parameters.at("x.a")), 2);
  EXPECT_EQ(std::get<std::int64_t>(r.parameters.at("x.b")), 10);
  EXPECT_EQ(std::get<std::int64_t>(r.parameters.at("nodes")), 3);
  EXPECT_EQ(r.seed, run_seed(7, 7));
  EXPECT_EQ(std::get<std::int64_t>(plan.run(5).parameters.at("x.b")), 30);
  EXPECT_THROW(plan.run(12), ValueError);
}

TEST(RunPlan, TenMillionPointsArePlannedLazily) {
  // 10^4 x 10^3 grid points: the plan holds the two axes (11000 values), not 10^7 points.
  const Experiment x =
      parse("[sweep]\n\"x.a\" = { range = [0, 10000] }\n\"x.b\" = { range = [0, 1000] }\n");
  const RunPlan plan(x);
  EXPECT_EQ(plan.points(), 10'000'000u);
  EXPECT_EQ(plan.size(), 10'000'000u);
  EXPECT_LT(plan.memory_bytes(), 11000 * sizeof(ParameterValue) + 4096);
  // Point p = a * 1000 + b (last axis fastest).
  for (const std::size_t p : {std::size_t{0}, std::size_t{1'234'567}, std::size_t{9'999'999}}) {
    const RunSpec r = plan.run(p);
    EXPECT_EQ(std::get<std::int64_t>(r.parameters.at("x.a")), static_cast<std::int64_t>(p / 1000));
    EXPECT_EQ(std::get<std::int64_t>(r.parameters.at("x.b")), static_cast<std::int64_t>(p % 1000));
    EXPECT_EQ(r.seed, run_seed(0, p));
  }
}

TEST(RunPlan, SamplesAboveTheMemoryLimitFailBeforeTheyAreDrawn) {
  set_memory_limit_bytes(std::uint64_t{1} << 20);
  // 10^6 samples x 2 values of at least 8 bytes each: far above 1 MiB.
  const Experiment x = parse(
      "[sampling]\nmethod = \"random\"\nsamples = 1000000\nseed = 3\n[sampling.parameters]\n"
      "\"x.u\" = { uniform = [10, 20] }\n\"x.v\" = { uniform = [0, 1] }\n");
  EXPECT_THROW(RunPlan{x}, MemoryLimitError);
  set_memory_limit_bytes(0);
}

TEST(RunPlan, SweepAxisAboveTheMemoryLimitFailsWhileParsing) {
  set_memory_limit_bytes(std::uint64_t{1} << 20);
  try {
    parse("[sweep]\n\"x.a\" = { range = [0, 1000000] }\n");
    ADD_FAILURE() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(e.file(), "t.toml");
    EXPECT_EQ(e.line(), 7);
    EXPECT_NE(e.message().find("a sweep axis of 1000000 values needs about"), std::string::npos)
        << e.message();
  }
  set_memory_limit_bytes(0);
}

TEST(Sampling, LatinHypercubeHitsEveryStratumOnce) {
  const Experiment x = parse(
      "[sampling]\nmethod = \"lhs\"\nsamples = 50\nseed = 3\n[sampling.parameters]\n"
      "\"x.u\" = { uniform = [10, 20] }\n\"x.l\" = { loguniform = [1, 1000] }\n"
      "\"x.i\" = { integers = [0, 49] }\n");
  const auto s = draw_samples(*x.sampling);
  ASSERT_EQ(s.size(), 50u * 3u);
  std::set<int> u_strata, l_strata, ints;
  for (std::size_t i = 0; i < 50; ++i) {
    const ParameterValue* row = s.data() + i * 3;
    const double u = std::get<double>(row[0]);
    const double l = std::get<double>(row[1]);
    ASSERT_GE(u, 10.0);
    ASSERT_LT(u, 20.0);
    ASSERT_GE(l, 1.0);
    ASSERT_LT(l, 1000.0);
    u_strata.insert(static_cast<int>((u - 10.0) / 10.0 * 50));
    l_strata.insert(static_cast<int>(std::log10(l) / 3.0 * 50));
    ints.insert(static_cast<int>(std::get<std::int64_t>(row[2])));
  }
  EXPECT_EQ(u_strata.size(), 50u);
  EXPECT_EQ(l_strata.size(), 50u);
  EXPECT_EQ(ints.size(), 50u);  // 50 strata of width 1 on 0..49: every integer once
  EXPECT_EQ(*ints.begin(), 0);
  EXPECT_EQ(*ints.rbegin(), 49);
}

TEST(Sampling, SameSeedSameSamplesOtherSeedOthers) {
  const std::string body =
      "[sampling]\nmethod = \"random\"\nsamples = 20\nseed = SEED\n[sampling.parameters]\n"
      "\"x.u\" = { uniform = [0, 1] }\n";
  auto with_seed = [&](int seed) {
    std::string b = body;
    b.replace(b.find("SEED"), 4, std::to_string(seed));
    return draw_samples(*parse(b).sampling);
  };
  EXPECT_EQ(with_seed(5), with_seed(5));
  EXPECT_NE(with_seed(5), with_seed(6));
  double mean = 0.0;
  const auto s = with_seed(5);
  ASSERT_EQ(s.size(), 20u);  // one parameter
  for (const ParameterValue& v : s) mean += std::get<double>(v) / 20.0;
  EXPECT_GT(mean, 0.2);
  EXPECT_LT(mean, 0.8);
}

TEST(RunPlan, SamplesAreCrossedWithTheGrid) {
  const Experiment x = parse(
      "[sweep]\n\"x.a\" = [1, 2, 3]\n[sampling]\nsamples = 4\n[sampling.parameters]\n"
      "\"x.u\" = { uniform = [0, 1] }\n");
  const RunPlan plan(x);
  EXPECT_EQ(plan.size(), 12u);
  // The same four samples under every grid point.
  for (std::size_t s = 0; s < 4; ++s) {
    EXPECT_EQ(plan.point_parameters(s).at("x.u"), plan.point_parameters(8 + s).at("x.u"));
  }
  EXPECT_EQ(std::get<std::int64_t>(plan.point_parameters(5).at("x.a")), 2);
}

}  // namespace
}  // namespace fspm::experiments
