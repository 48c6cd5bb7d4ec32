// fspm greenlab simulate | reconstruct | fit, run as a user would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/greenlab/" + name;
}

// Jaeger et al. 2010, Figure 1: 6 metamers explicitly, 4 node records compressed.
TEST(GreenlabCli, SimulateJaegerFigure1) {
  const auto dir = scratch_dir("greenlab_sim");
  const std::string out = (dir / "fig1.ctree").string();
  const auto r =
      run_fspm("greenlab simulate " + example("jaeger_figure1.toml") + " -o " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["cycles"], 2);
  EXPECT_EQ(j["graph_nodes"], 4);
  EXPECT_EQ(j["metamers"], 6);
  EXPECT_EQ(j["leaves"], 4);  // leaf life span 1: the leaves of cycle 2
  EXPECT_EQ(j["graph_bytes"], std::filesystem::file_size(out));
  EXPECT_EQ(j["metamers_by_age"], nlohmann::json({{"1", 6}}));
}

TEST(GreenlabCli, SimulateCyclesOverrideAndReconstructAtEveryAge) {
  const auto dir = scratch_dir("greenlab_rec");
  const std::string ctree = (dir / "bin.ctree").string();
  // Binary tree: 2 (2^N - 1) metamers.
  auto r = run_fspm("greenlab simulate " + example("jaeger_figure1.toml") + " --cycles 5 -o " +
                    ctree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["metamers"], 62);
  for (int age : {1, 3, 5}) {
    const std::string tree = (dir / ("bin_" + std::to_string(age) + ".tree")).string();
    r = run_fspm("greenlab reconstruct " + ctree + " --age " + std::to_string(age) + " -o " + tree +
                 " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const int metamers = 2 * ((1 << age) - 1);
    const int leaves = 2 * (1 << (age - 1));  // one-cycle leaves on the last units
    EXPECT_EQ(j["age"], age);
    EXPECT_EQ(j["metamers"], metamers);
    EXPECT_EQ(j["components"], metamers + leaves);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);
    const TreeGraph t = read_tree_file(tree);
    EXPECT_EQ(t.size(), static_cast<std::size_t>(metamers + leaves + (1 << (age - 1)) - 1));
  }
  r = run_fspm("greenlab reconstruct " + ctree + " --age 6 -o " + (dir / "x.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("simulated to age"), std::string::npos) << r.err;
}

TEST(GreenlabCli, BadPlantDescriptionNamesKeyAndLine) {
  const auto dir = scratch_dir("greenlab_bad");
  const auto params = dir / "plant.toml";
  std::ofstream(params) << "[plant]\ncycles = 3\n[[age]]\nindex = 1\nduration = 1\nnext_age = 0\n"
                           "units = [ { count = 1 } ]\nsurvival_probability = 2.0\n";
  const auto r =
      run_fspm("greenlab simulate " + params.string() + " -o " + (dir / "p.ctree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("plant.toml:8"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("survival_probability"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "p.ctree"));
  const auto c =
      run_fspm("greenlab reconstruct " + params.string() + " -o " + (dir / "t.tree").string());
  EXPECT_EQ(c.exit_code, 1);
  EXPECT_NE(c.err.find("not a .ctree file"), std::string::npos) << c.err;
}

// The example targets were made with resistance 0.8, age.1.internode_sink 0.6, age.2.leaf_sink
// 0.7, age.1.leaf_beta_a 2.5 and 1% noise (see examples/greenlab/gl1_plant.toml).
TEST(GreenlabCli, FitRecoversExampleParameters) {
  const auto dir = scratch_dir("greenlab_fit");
  const std::string out = (dir / "fitted.toml").string();
  auto r = run_fspm("greenlab fit " + example("gl1_plant.toml") + " " + example("gl1_targets.csv") +
                    " -o " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_LT(j["cost"].get<double>(), j["initial_cost"].get<double>());
  const std::vector<double> truth{0.8, 0.6, 0.7, 2.5};
  ASSERT_EQ(j["parameters"].size(), truth.size());
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const auto& p = j["parameters"][i];
    EXPECT_NEAR(p["estimate"].get<double>(), truth[i], 4 * p["std_error"].get<double>())
        << p["name"];
  }
  EXPECT_TRUE(std::filesystem::exists(out));
  // The fitted file is a valid plant description again.
  r = run_fspm("greenlab simulate " + out + " -o " + (dir / "f.ctree").string() + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // One iteration is not enough: reported with the final cost, exit 1.
  r = run_fspm("greenlab fit " + example("gl1_plant.toml") + " " + example("gl1_targets.csv") +
               " -o " + out + " --max-iterations 1");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("did not converge"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("final cost"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fspm
