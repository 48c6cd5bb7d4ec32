// fspm lsystem derive | interpret, run as a user would.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>
#include <vector>

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

// The end points of a tree's nodes, sorted on a grid far finer than the drawing.
std::vector<Eigen::Vector3d> sorted_ends(const TreeGraph& t) {
  std::vector<Eigen::Vector3d> ends;
  for (NodeId n = 0; n < t.size(); ++n) ends.push_back(t.end(n));
  const auto key = [](const Eigen::Vector3d& p) {
    return std::make_tuple(std::llround(p.x() * 1e6), std::llround(p.y() * 1e6),
                           std::llround(p.z() * 1e6));
  };
  std::sort(ends.begin(), ends.end(),
            [&](const auto& a, const auto& b) { return key(a) < key(b); });
  return ends;
}

// Fig. 1.24a at n = 4 written as a .ctree: a group per prototype (the axiom and F after 1..4
// remaining steps) and the five internodes of F(1), standing for 5^4 internodes. fspm greenlab
// reconstruct expands it into the explicit turtle's tree (an independent implementation: the
// string derived and drawn module by module); interpret -o .ctree writes the same file, and
// fspm mesh meshes the .l and the .ctree alike.
TEST(LsystemCli, CompressedDeriveWritesACtreeTheGreenLabReadersExpand) {
  const auto dir = scratch_dir("lsystem_ctree");
  const std::string l = example("abop_1_24a.l");
  const std::string ctree = (dir / "a.ctree").string(), again = (dir / "b.ctree").string();
  auto r = run_fspm("lsystem derive " + l + " --steps 4 --compressed -o " + ctree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["symbols"]["F"], 625);
  EXPECT_EQ(j["ctree_records"], 5 + 5);
  EXPECT_EQ(j["ctree_organs"], 625);
  EXPECT_EQ(j["ctree_bytes"], std::filesystem::file_size(ctree));
  EXPECT_TRUE(j.contains("graph_nodes") && j.contains("graph_bytes") && j.contains("compression"));
  r = run_fspm("lsystem interpret " + l + " --steps 4 --compressed -o " + again);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream fa(ctree, std::ios::binary), fb(again, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(fa), {}),
            std::string(std::istreambuf_iterator<char>(fb), {}));

  const std::string rebuilt = (dir / "rebuilt.tree").string(),
                    plain = (dir / "plain.tree").string();
  r = run_fspm("greenlab reconstruct " + ctree + " -o " + rebuilt + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["metamers"], 625);
  ASSERT_EQ(run_fspm("lsystem interpret " + l + " --steps 4 -o " + plain).exit_code, 0);
  const auto a = sorted_ends(read_tree_file(rebuilt)), b = sorted_ends(read_tree_file(plain));
  ASSERT_EQ(a.size(), 625u);
  ASSERT_EQ(b.size(), 625u);
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_LT((a[i] - b[i]).norm(), 1e-6) << i;

  const std::string from_l = (dir / "l.obj").string(), from_ctree = (dir / "c.obj").string();
  r = run_fspm("mesh " + l + " --steps 4 --compressed -o " + from_l + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto mesh_l = nlohmann::json::parse(r.out);
  EXPECT_EQ(mesh_l["lsystem"]["prototypes"], 5);
  r = run_fspm("mesh " + ctree + " -o " + from_ctree + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["triangles"], mesh_l["triangles"]);
  EXPECT_GT(mesh_l["triangles"].get<int>(), 0);
}

// The subtree of `n` as a string, children in sorted order: equal for isomorphic labelled trees.
std::string canonical(const TreeGraph& t, NodeId n, const std::function<int(NodeId)>& label) {
  std::vector<std::string> children;
  for (const NodeId c : t.children(n)) children.push_back(canonical(t, c, label));
  std::sort(children.begin(), children.end());
  std::string out = "(" + std::to_string(label(n));
  for (const auto& c : children) out += c;
  return out + ")";
}

// Jaeger et al. 2010, 2.1.3: the grammar B0 --> M0 [B1] B0, B1 --> M1 [B2] B1, B2 --> M2 B2
// (examples/lsystems/greenlab.l, metamers of ages 0, 1, 2 drawn 1, 0.6 and 0.35 long) is the
// dual-scale automaton of a GreenLab plant whose ages 1 and 2 make one metamer per cycle bearing
// one bud of the next age, age 3 one metamer per cycle, every bud growing the cycle after it
// appears. After 6 cycles both give the same tree node for node: 6 + 15 + 20 metamers (the
// closed forms n, n(n-1)/2, n(n-1)(n-2)/6), as the GreenLab simulator's graph reconstructs it,
// as the L-system's turtle draws it, and as the L-system's .ctree expands.
TEST(LsystemCli, GreenLabGrammarGivesTheGreenLabSimulatorsTree) {
  const auto dir = scratch_dir("lsystem_greenlab");
  std::ofstream(dir / "grammar.toml") << R"([plant]
cycles = 6
[[age]]
index = 1
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 2, count = 1 } ] } ]
[[age]]
index = 2
duration = 100
next_age = 0
units = [ { count = 1, axillary = [ { age = 3, count = 1 } ] } ]
[[age]]
index = 3
duration = 100
next_age = 0
units = [ { count = 1 } ]
)";
  const std::string gl = (dir / "gl.ctree").string(), gl_tree = (dir / "gl.tree").string();
  auto r = run_fspm("greenlab simulate " + (dir / "grammar.toml").string() + " -o " + gl);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("greenlab reconstruct " + gl + " --no-leaves -o " + gl_tree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string l = example("greenlab.l"), l_tree = (dir / "l.tree").string();
  const std::string l_ctree = (dir / "l.ctree").string(), l_back = (dir / "l_back.tree").string();
  ASSERT_EQ(run_fspm("lsystem interpret " + l + " -o " + l_tree).exit_code, 0);
  ASSERT_EQ(run_fspm("lsystem derive " + l + " --compressed -o " + l_ctree).exit_code, 0);
  r = run_fspm("greenlab reconstruct " + l_ctree + " -o " + l_back);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const TreeGraph greenlab = read_tree_file(gl_tree);
  const TreeGraph drawn = read_tree_file(l_tree), expanded = read_tree_file(l_back);
  ASSERT_EQ(greenlab.size(), 41u);
  std::map<int, int> by_age;
  for (NodeId n = 0; n < greenlab.size(); ++n) ++by_age[greenlab.physiological_age(n)];
  EXPECT_EQ(by_age, (std::map<int, int>{{1, 6}, {2, 15}, {3, 20}}));
  // The homomorphism's lengths name the ages of the L-system's metamers.
  const auto age_of_length = [](const TreeGraph& t) {
    return [&t](NodeId n) {
      const double len = t.length(n);
      return std::abs(len - 1.0) < 1e-9 ? 1 : std::abs(len - 0.6) < 1e-9 ? 2 : 3;
    };
  };
  const std::string expected =
      canonical(greenlab, 0, [&](NodeId n) { return greenlab.physiological_age(n); });
  EXPECT_EQ(canonical(drawn, 0, age_of_length(drawn)), expected);
  // Every substructure B_i draws its own metamer first, so each placed one hangs from the
  // metamer before it, as in the explicit drawing.
  EXPECT_EQ(canonical(expanded, 0, age_of_length(expanded)), expected);
}

TEST(LsystemCli, LsystemOptionsOfOtherFilesAndOutputsAreRefused) {
  const auto dir = scratch_dir("lsystem_ctree_bad");
  auto r = run_fspm("lsystem derive " + example("abop_1_24a.l") + " --compressed -o " +
                    (dir / "a.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(".ctree"), std::string::npos) << r.err;
  ASSERT_EQ(run_fspm("lsystem interpret " + example("abop_1_24a.l") + " --steps 2 -o " +
                     (dir / "a.tree").string())
                .exit_code,
            0);
  r = run_fspm("mesh " + (dir / "a.tree").string() + " --compressed -o " +
               (dir / "a.obj").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("(.l)"), std::string::npos) << r.err;
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
