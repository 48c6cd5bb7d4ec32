#include "experiments/adapt_model.hpp"

#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

// An opaque wall as tall as the sky matters, its face at x = wall_x.
std::string wall_json(double wall_x) {
  return R"({ "sky": { "model": "cos2", "brightest": [0, 0, 1], "directions": 64 },
  "occluders": [ { "type": "wall", "from": [)" +
         std::to_string(wall_x) + R"(, -20], "to": [)" + std::to_string(wall_x) +
         R"(, 20], "height": 8, "thickness": 0.2 } ] })";
}

struct Fixture {
  std::filesystem::path dir;
  std::unique_ptr<Model> model;
  explicit Fixture(const std::string& name) : dir(testing::scratch(name)) {
    // A fixed open-grown input: the shipped 12-year tree of type A, so these tests do not move
    // when the growth model does.
    write_tree_file(read_tree_file(FSPM_SOURCE_DIR "/examples/trees/open_a12.treeb"),
                    (dir / "open.tree").string());
    testing::write(dir / "wall.json", wall_json(1.5));
    testing::write(dir / "wall_near.json", wall_json(0.5));
    model =
        make_adapt_model((dir / "open.tree").string(), (dir / "wall.json").string(), dir.string());
  }
  RunResult run(ParameterSet p) const { return model->run(p, 1, RunContext{}); }
};

TEST(AdaptModel, AnOpenSceneOrAFarWallLeavesTheTreeAsGrown) {
  const Fixture f("adapt_open");
  const TreeGraph grown = read_tree_file((f.dir / "open.tree").string());
  const RunResult open = f.run({{"scene", std::string("open")}});
  EXPECT_EQ(open.metrics.at("pruned_nodes"), 0.0);
  EXPECT_LT(open.metrics.at("tip_displacement"), 1e-9);
  EXPECT_EQ(open.metrics.at("nodes"), static_cast<double>(grown.size()));
  // 200 m from the wall the tree sees the open sky again.
  const RunResult far = f.run({{"tree_x_m", -200.0}});
  EXPECT_EQ(far.metrics.at("pruned_nodes"), 0.0);
  EXPECT_LT(far.metrics.at("tip_displacement"), 1e-9);
}

TEST(AdaptModel, MovingTheTreeIsMovingTheWallTheOtherWay) {
  const Fixture f("adapt_move");
  // The tree 1 m east in front of the wall at x = 1.5 stands as the tree at the origin in front
  // of the wall at x = 0.5 (a separate scene file).
  const RunResult moved = f.run({{"tree_x_m", 1.0}});
  const RunResult near = f.run({{"scene", std::string("wall_near.json")}});
  EXPECT_EQ(moved.metrics.at("pruned_nodes"), near.metrics.at("pruned_nodes"));
  EXPECT_NEAR(moved.metrics.at("tip_displacement"), near.metrics.at("tip_displacement"), 1e-9);
  EXPECT_NEAR(moved.metrics.at("light_interception"), near.metrics.at("light_interception"), 1e-9);
  // Closer to the wall: more of the crown is shaded, pruned and bent than at 1.5 m.
  const RunResult at = f.run({});
  EXPECT_GT(near.metrics.at("pruned_nodes"), 0.0);
  EXPECT_GE(near.metrics.at("pruned_nodes"), at.metrics.at("pruned_nodes"));
  EXPECT_LT(near.metrics.at("light_interception"), at.metrics.at("light_interception"));
  // The same analysis served all three runs (one analysis, one time).
  EXPECT_EQ(moved.metrics.at("analysis_seconds"), at.metrics.at("analysis_seconds"));
  ASSERT_TRUE(near.tree.has_value());
  EXPECT_EQ(near.metrics.at("nodes") + near.metrics.at("pruned_nodes"),
            static_cast<double>(read_tree_file((f.dir / "open.tree").string()).size()));
}

TEST(AdaptModel, AnalysisParametersChangeTheResult) {
  const Fixture f("adapt_params");
  const RunResult strong = f.run({{"tree_x_m", 1.0}, {"pruning_strength", 1.5}});
  const RunResult none = f.run({{"tree_x_m", 1.0}, {"pruning_strength", 0.0}});
  EXPECT_LT(none.metrics.at("pruned_nodes"), strong.metrics.at("pruned_nodes"));
  // c_psi = 0 makes every minimum pruning factor 0 (eq. 4.12): nothing is pruned for its light,
  // so in the open nothing is pruned at all (beside the wall, thick branches that stand in it
  // cannot bend out and are pruned as blocked).
  const RunResult none_open = f.run({{"scene", std::string("open")}, {"pruning_strength", 0.0}});
  EXPECT_EQ(none_open.metrics.at("pruned_nodes"), 0.0);
}

TEST(AdaptModel, BadParametersAndFilesAreRejectedBeforeRunning) {
  const Fixture f("adapt_bad");
  EXPECT_THROW(f.model->check_parameter("no_such_key", 1.0), ValueError);
  EXPECT_THROW(f.model->check_parameter("gamma0", 2.0), ValueError);
  EXPECT_THROW(f.model->check_parameter("temporal_pruning", std::int64_t{2}), ValueError);
  EXPECT_THROW(f.model->check_parameter("tree_x_m", std::string("east")), ValueError);
  EXPECT_THROW(f.model->check_parameter("scene", std::string("missing.json")), IoError);
  EXPECT_NO_THROW(f.model->check_parameter("phototropism", 0.4));
  EXPECT_NO_THROW(f.model->check_parameter("scene", std::string("open")));
  EXPECT_THROW(make_adapt_model((f.dir / "missing.tree").string(), "", f.dir.string()), IoError);
}

}  // namespace
}  // namespace fspm::experiments
