// Model kind "stages" on a tree whose stages follow in closed form: one vertical chain of four
// unit internodes grows at the constant rate of Pirk eq. 5.4, l(t) = 4 t.
#include "experiments/stages_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "experiments/experiment.hpp"
#include "experiments/model_factory.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

std::string chain_file(const std::string& name) {
  TreeGraph t;
  NodeId parent = kNoNode;
  for (int k = 0; k < 4; ++k) {
    NodeData d;
    d.start = Eigen::Vector3d(0, 0, k);
    d.direction = Eigen::Vector3d::UnitZ();
    d.end = Eigen::Vector3d(0, 0, k + 1);
    d.length = 1.0;
    d.radius = 0.1;
    parent = t.add_node(parent, d);
  }
  const std::string path = (testing::scratch(name) / "chain.tree").string();
  write_tree_file(t, path);
  return path;
}

TEST(StagesModel, AStageOfAChainIsItsLengthAtTheConstantRate) {
  const auto model = make_stages_model(chain_file("stages_chain"));
  for (const double t : {0.2, 0.5, 0.9, 1.0}) {
    const RunResult r = model->run({{"t", t}}, 1, RunContext{});
    EXPECT_NEAR(r.metrics.at("height"), 4.0 * t, 1e-9) << t;
    EXPECT_NEAR(r.metrics.at("total_length"), 4.0 * t, 1e-9) << t;
    EXPECT_EQ(r.metrics.at("internodes"), std::ceil(4.0 * t - 1e-12)) << t;
    EXPECT_GE(r.metrics.at("stage_seconds"), 0.0);
    ASSERT_TRUE(r.tree.has_value());
    EXPECT_EQ(static_cast<double>(r.tree->size()), r.metrics.at("nodes"));
  }
  // Without t the run is the given tree.
  EXPECT_NEAR(model->run({}, 1, RunContext{}).metrics.at("height"), 4.0, 1e-9);
}

TEST(StagesModel, WrongParametersAreRefusedByName) {
  const auto model = make_stages_model(chain_file("stages_wrong"));
  EXPECT_THROW(model->check_parameter("t", 1.5), ValueError);
  EXPECT_THROW(model->check_parameter("season_years", std::int64_t{-1}), ValueError);
  EXPECT_THROW(model->check_parameter("years", std::int64_t{3}), ValueError);
  try {
    model->check_parameter("continuation", std::string("thickset"));
    FAIL() << "a misspelt continuation was accepted";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("thickest"), std::string::npos) << e.what();
  }
  model->check_parameter("continuation", std::string("least_deviation"));
  EXPECT_THROW(make_stages_model("no_such_tree.tree"), IoError);
}

TEST(StagesModel, AnExperimentFileNamesTheKind) {
  const std::string tree = chain_file("stages_file");
  const Experiment x = parse_experiment(
      "[experiment]\nname = \"s\"\n[model]\nkind = \"stages\"\n"
      "file = \"" +
      tree + "\"\n[sweep]\nt = [0.25, 0.75]\n");
  const auto model = make_model(x);
  EXPECT_NEAR(model->run({{"t", 0.25}}, 1, RunContext{}).metrics.at("height"), 1.0, 1e-9);
}

}  // namespace
}  // namespace fspm::experiments
