// fspm lsystem derive | interpret, run as a user would.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/" + name;
}

TEST(LsystemCli, DeriveJsonCountsFollowTheClosedForm) {
  // ABOP 1.24a after n steps: F = 5^n, [ = ] = (5^n - 1)/2, + = - = (5^n - 1)/4.
  const auto r = run_fspm("lsystem derive " + example("abop_1_24a.l") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["steps"], 5);
  EXPECT_EQ(j["symbols"]["F"], 3125);
  EXPECT_EQ(j["symbols"]["["], 1562);
  EXPECT_EQ(j["symbols"]["]"], 1562);
  EXPECT_EQ(j["symbols"]["+"], 781);
  EXPECT_EQ(j["symbols"]["-"], 781);
  EXPECT_EQ(j["modules"], 3125 + 2 * 1562 + 2 * 781);
  EXPECT_FALSE(j.contains("string"));
}

// n = 20 is 2.4 * 10^14 modules: only the substructure graph holds it. Counts from the closed
// form above; at n = 5 the compressed and explicit derivations print the same counts.
TEST(LsystemCli, CompressedDeriveCountsStringsTooLargeToHold) {
  const auto r =
      run_fspm("lsystem derive " + example("abop_1_24a.l") + " --steps 20 --compressed --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const std::uint64_t f = 95367431640625;  // 5^20
  EXPECT_EQ(j["compressed"], true);
  EXPECT_EQ(j["symbols"]["F"], f);
  EXPECT_EQ(j["symbols"]["["], (f - 1) / 2);
  EXPECT_EQ(j["symbols"]["+"], (f - 1) / 4);
  EXPECT_LE(j["graph_nodes"].get<int>(), 25);
  EXPECT_LT(j["graph_bytes"].get<double>(), 1e6);
  EXPECT_GT(j["compression"].get<double>(), 1e9);
  const auto small = nlohmann::json::parse(
      run_fspm("lsystem derive " + example("monopodial_tree.l") + " --compressed --json").out);
  const auto expl = nlohmann::json::parse(
      run_fspm("lsystem derive " + example("monopodial_tree.l") + " --json").out);
  EXPECT_EQ(small["symbols"], expl["symbols"]);
  EXPECT_EQ(small["modules"], expl["modules"]);
}

TEST(LsystemCli, CompressedDeriveOfAContextSensitiveSystemSaysWhyAndDerivesExplicitly) {
  const auto r =
      run_fspm("lsystem derive " + example("context_sensitive_plant.l") + " --compressed --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["compressed"], false);
  EXPECT_NE(j["why_not_compressed"].get<std::string>().find("context-sensitive"),
            std::string::npos);
  EXPECT_NE(r.err.find("context-sensitive"), std::string::npos) << r.err;
  const auto plain = nlohmann::json::parse(
      run_fspm("lsystem derive " + example("context_sensitive_plant.l") + " --json").out);
  EXPECT_EQ(j["modules"], plain["modules"]);
}

TEST(LsystemCli, DeriveStringStepsDefineAndSeed) {
  const auto r = run_fspm("lsystem derive " + example("parametric_tree.l") +
                          " --steps 1 --define R=2 --string --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["steps"], 1);
  EXPECT_EQ(j["string"], "F(1)[+A(0.5)][-A(0.5)]");
  const auto a = run_fspm("lsystem derive " + example("stochastic_plant.l") + " --seed 3 --string");
  const auto b = run_fspm("lsystem derive " + example("stochastic_plant.l") + " --seed 3 --string");
  const auto c = run_fspm("lsystem derive " + example("stochastic_plant.l") + " --seed 4 --string");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
}

TEST(LsystemCli, InterpretWritesATreeFile) {
  const auto dir = scratch_dir("lsystem_interpret");
  const std::string out = (dir / "mono.tree").string();
  const auto r = run_fspm("lsystem interpret " + example("monopodial_tree.l") + " -o " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph tree = read_tree_file(out);
  EXPECT_EQ(tree.size(), 1023u);  // 2^10 - 1 internodes (one F per apex per step)
  EXPECT_NEAR(tree.length(0), 1.0, 1e-9);
  // !(10) in pixels (the view file's unit) of a picture 500 pixels across the plant's largest
  // extent, its height: the trunk of lengths 0.9^k, k < 10, sum (1 - 0.9^10) / 0.1.
  const double height = (1.0 - std::pow(0.9, 10)) / 0.1;
  EXPECT_NEAR(tree.radius(0), 0.5 * 10.0 * height / 500.0, 1e-9);
}

// Fig. 1.24a at n = 5 drawn by instancing: F after 1..5 remaining steps and the axiom are the six
// prototypes, F(1) (five internodes) is placed 5^4 times, and the expanded tree has the explicit
// drawing's 5^5 internodes in the same box. At n = 20 (9.5 * 10^13 internodes) the mesh is
// refused before anything is built, naming --detail.
TEST(LsystemCli, CompressedInterpretDrawsByInstancing) {
  const auto dir = scratch_dir("lsystem_interpret_compressed");
  const std::string tree = (dir / "a.tree").string(), plain = (dir / "b.tree").string();
  auto r = run_fspm("lsystem interpret " + example("abop_1_24a.l") + " --compressed -o " + tree +
                    " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["prototypes"], 6);
  EXPECT_EQ(j["instances"], 625);
  EXPECT_EQ(j["represented_segments"], 3125);
  ASSERT_EQ(run_fspm("lsystem interpret " + example("abop_1_24a.l") + " -o " + plain).exit_code, 0);
  const TreeGraph a = read_tree_file(tree), b = read_tree_file(plain);
  ASSERT_EQ(a.size(), 3125u);
  ASSERT_EQ(b.size(), 3125u);
  Eigen::AlignedBox3d box_a, box_b;
  for (NodeId n = 0; n < a.size(); ++n) {
    box_a.extend(a.end(n));
    box_b.extend(b.end(n));
  }
  EXPECT_LT((box_a.min() - box_b.min()).norm() + (box_a.max() - box_b.max()).norm(), 1e-9);
  const std::string glb = (dir / "a.glb").string();
  r = run_fspm("lsystem interpret " + example("abop_1_24a.l") + " --compressed -o " + glb +
               " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["mesh_instances"], 625);
  r = run_fspm("lsystem interpret " + example("abop_1_24a.l") + " --compressed --steps 20 -o " +
               glb);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--detail"), std::string::npos) << r.err;
}

TEST(LsystemCli, BadInputExitsOneWithPosition) {
  const auto dir = scratch_dir("lsystem_bad");
  std::ofstream(dir / "bad.l") << "Axiom: F\nF --> F(1 +)\n";
  auto r = run_fspm("lsystem derive " + (dir / "bad.l").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.l:2:"), std::string::npos) << r.err;
  r = run_fspm("lsystem derive " + example("abop_1_24a.l") + " --steps 12 --budget 1000");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("budget"), std::string::npos) << r.err;
  r = run_fspm("lsystem derive " + example("abop_1_24a.l") + " --define NOEQUALS");
  EXPECT_EQ(r.exit_code, 1);
}

}  // namespace
}  // namespace fspm
