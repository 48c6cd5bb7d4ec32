#include "experiments/grow_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

// An opaque wall 1.5 m east of the tree, no ground: "open" then means the sky alone, as "O".
const char* kWall = R"({ "sky": { "model": "cos2", "brightest": [0, 0, 1], "directions": 64 },
  "occluders": [ { "type": "wall", "from": [1.5, -10], "to": [1.5, 10], "height": 5,
                   "thickness": 0.2 } ] })";

struct Fixture {
  std::filesystem::path dir;
  std::unique_ptr<Model> model;
  explicit Fixture(const std::string& name) : dir(testing::scratch(name)) {
    testing::write(dir / "wall.json", kWall);
    model = make_grow_model("", (dir / "wall.json").string(), dir.string());
  }
  RunResult run(const std::string& set, std::uint64_t seed, bool regrowth = false) const {
    ParameterSet p{{"preset", std::string("A")}, {"years", std::int64_t{7}}, {"set", set}};
    if (regrowth) p["measure_regrowth"] = std::int64_t{1};
    return model->run(p, seed, RunContext{});
  }
};

TEST(GrowModel, SetOIgnoresTheObstaclesAndGMeetsThem) {
  const Fixture f("grow_sets");
  const RunResult o = f.run("O", 3);
  ParameterSet open{{"preset", std::string("A")},
                    {"years", std::int64_t{7}},
                    {"set", std::string("G")},
                    {"scene", std::string("open")}};
  const RunResult g_open = f.model->run(open, 3, RunContext{});
  // O in the walled scene is G without a scene: the same tree for the same seed.
  EXPECT_EQ(o.metrics.at("nodes"), g_open.metrics.at("nodes"));
  EXPECT_DOUBLE_EQ(o.metrics.at("height"), g_open.metrics.at("height"));
  const RunResult g = f.run("G", 3);
  // The wall shades the east half of the sky: less light is intercepted by the walled tree.
  EXPECT_LT(g.metrics.at("light_interception"), o.metrics.at("light_interception"));
  EXPECT_FALSE(o.metrics.contains("adapt_seconds"));
  ASSERT_TRUE(o.tree.has_value());
  EXPECT_EQ(static_cast<double>(o.tree->size()), o.metrics.at("nodes"));
}

TEST(GrowModel, SetTIsTheOpenTreeAdaptedAndPruned) {
  const Fixture f("grow_t");
  const RunResult o = f.run("O", 9);
  const RunResult t = f.run("T", 9, true);
  ASSERT_TRUE(t.tree.has_value());
  EXPECT_GE(t.metrics.at("adapt_seconds"), 0.0);
  EXPECT_GE(t.metrics.at("regrow_seconds"), 0.0);
  // The adapted tree is the open-grown one minus what the adaptation pruned.
  EXPECT_EQ(t.metrics.at("nodes") + t.metrics.at("pruned_nodes"), o.metrics.at("nodes"));
  EXPECT_GT(t.metrics.at("tip_displacement"), 0.0);
}

// Adapting to the open sky changes nothing, so every metric of set T equals set O's; the light
// interception of both comes from the same leaf clusters.
TEST(GrowModel, SetTInTheOpenIsSetO) {
  const Fixture f("grow_t_open");
  ParameterSet p{
      {"preset", std::string("A")}, {"years", std::int64_t{7}}, {"scene", std::string("open")}};
  p["set"] = std::string("O");
  const RunResult o = f.model->run(p, 4, RunContext{});
  p["set"] = std::string("T");
  const RunResult t = f.model->run(p, 4, RunContext{});
  EXPECT_EQ(t.metrics.at("pruned_nodes"), 0.0);
  EXPECT_EQ(t.metrics.at("nodes"), o.metrics.at("nodes"));
  EXPECT_NEAR(t.metrics.at("height"), o.metrics.at("height"), 1e-9);
  EXPECT_NEAR(t.metrics.at("light_interception"), o.metrics.at("light_interception"),
              1e-9 * o.metrics.at("light_interception"));
}

// Set T's adaptation takes its cluster light from adapt_light_model: the adaptation's own default
// (the one `fspm adapt` uses, AnalysisParams) without it, and the shadow grid is another light,
// so the same open tree is adapted differently.
TEST(GrowModel, AdaptLightModelChoosesSetTsClusterLight) {
  const Fixture f("grow_adapt_light");
  ParameterSet p{{"preset", std::string("A")}, {"years", std::int64_t{7}}};
  p["set"] = std::string("T");
  const RunResult by_default = f.model->run(p, 9, RunContext{});
  p["adapt_light_model"] =
      std::string(environment::cluster_light_model_name(environment::AnalysisParams{}.light_model));
  const RunResult named = f.model->run(p, 9, RunContext{});
  p["adapt_light_model"] = std::string("shadow_grid");
  const RunResult grid = f.model->run(p, 9, RunContext{});
  EXPECT_EQ(named.metrics.at("nodes"), by_default.metrics.at("nodes"));
  EXPECT_EQ(named.metrics.at("tip_displacement"), by_default.metrics.at("tip_displacement"));
  EXPECT_NE(grid.metrics.at("tip_displacement"), named.metrics.at("tip_displacement"));
  // Either way the adapted tree is the open one minus what was pruned.
  EXPECT_EQ(grid.metrics.at("nodes") + grid.metrics.at("pruned_nodes"),
            named.metrics.at("nodes") + named.metrics.at("pruned_nodes"));
  EXPECT_THROW(f.model->check_parameter("adapt_light_model", std::string("sunny")), ValueError);
  EXPECT_NO_THROW(f.model->check_parameter("adapt_light_model", std::string("shadow_grid")));
}

TEST(GrowModel, BadParametersAreRejectedBeforeRunning) {
  const Fixture f("grow_bad");
  EXPECT_THROW(f.model->check_parameter("set", std::string("X")), ValueError);
  EXPECT_THROW(f.model->check_parameter("no_such_key", 1.0), Error);
  EXPECT_THROW(f.model->check_parameter("phototropism", 3.0), ValueError);
  EXPECT_THROW(f.model->check_parameter("scene", std::string("missing.json")), IoError);
  EXPECT_NO_THROW(f.model->check_parameter("preset", std::string("B")));
  EXPECT_THROW(f.model->check_parameter("preset", std::string("Z")), ValueError);
}

}  // namespace
}  // namespace fspm::experiments

namespace fspm::experiments {
namespace {

// With a real sky in the growth parameters the runs record the PAR the leaves absorb; the tree
// beside the wall absorbs less (its own size and the wall's shade). The canopy light metrics hold
// together: sunlit + shaded leaf area, STAR = G x LIE with G = 0.5, LIE within (0, 1].
TEST(GrowModel, RealSkyGivesAbsorbedPar) {
  const std::filesystem::path dir = testing::scratch("grow_real_sky");
  testing::write(dir / "wall.json", kWall);
  testing::write(dir / "sky.toml",
                 "preset = \"A\"\nsky = { site = { latitude = 50, longitude = 8, elevation = 200, "
                 "utc_offset = 1 }, date = \"2024-06-01\" }\n");
  const auto model =
      make_grow_model((dir / "sky.toml").string(), (dir / "wall.json").string(), dir.string());
  const auto run = [&](const char* set) {
    return model->run({{"years", std::int64_t{7}}, {"set", std::string(set)}}, 3, RunContext{});
  };
  const RunResult o = run("O"), g = run("G");
  for (const RunResult* r : {&o, &g}) {
    ASSERT_TRUE(r->metrics.contains("absorbed_par"));
    EXPECT_GT(r->metrics.at("absorbed_par"), 0.0);
    const double lie = r->metrics.at("light_interception_efficiency");
    EXPECT_GT(lie, 0.0);
    EXPECT_LE(lie, 1.0);
    EXPECT_NEAR(r->metrics.at("star"), 0.5 * lie, 1e-12);
    EXPECT_GT(r->metrics.at("sunlit_leaf_area"), 0.0);
    EXPECT_GT(r->metrics.at("shaded_leaf_area"), 0.0);
  }
  std::printf("absorbed PAR: open %.2f mol/day, beside the wall %.2f mol/day\n",
              o.metrics.at("absorbed_par"), g.metrics.at("absorbed_par"));
  EXPECT_GT(o.metrics.at("absorbed_par"), g.metrics.at("absorbed_par"));
  const Fixture plain("grow_cos2_sky");
  const RunResult c = plain.run("O", 3);
  EXPECT_FALSE(c.metrics.contains("absorbed_par"));
  EXPECT_TRUE(c.metrics.contains("light_interception_efficiency"));
}

}  // namespace
}  // namespace fspm::experiments
