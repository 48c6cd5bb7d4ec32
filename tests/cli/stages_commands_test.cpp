// fspm stages, run as a user would.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "fspm/tree_file.hpp"
#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

const std::string kTree = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";

TEST(StagesCli, TheLastStageIsTheGivenTreeAndStagesGrow) {
  const auto dir = scratch_dir("stages");
  auto r = run_fspm("stages " + kTree + " --at 1 -o " + (dir / "last.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph given = read_tree_file(kTree);
  const TreeGraph last = read_tree_file((dir / "last.tree").string());
  ASSERT_EQ(last.size(), given.size());
  for (NodeId i = 0; i < given.size(); ++i) {
    ASSERT_LT((last.end(i) - given.end(i)).norm(), 1e-9) << i;
    ASSERT_NEAR(last.radius(i), given.radius(i), 1e-9) << i;
  }
  r = run_fspm("stages " + kTree + " --steps 5 -o " + (dir / "seq").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["stages"], 5);
  EXPECT_GT(j["chains"].get<int>(), 1);
  // Internodes only grow in number (leaves move from tip to tip).
  const auto internodes = [](const TreeGraph& g) {
    std::size_t n = 0;
    for (NodeId i = 0; i < g.size(); ++i) n += g.kind(i) == OrganKind::kInternode;
    return n;
  };
  std::size_t previous = 0;
  for (int k = 1; k <= 5; ++k) {
    const auto path = dir / "seq" / ("stage_00" + std::to_string(k) + ".treeb");
    const std::size_t n = internodes(read_tree_file(path.string()));
    EXPECT_GE(n, previous) << path;
    previous = n;
  }
  EXPECT_EQ(previous, internodes(given));
}

// --added keeps the last stage the given tree; --profile sums, over its layers, every leaf and
// all the wood (pi r^2 l) of the given tree, by either clipping method.
TEST(StagesCli, AddedBranchesAndProfileDiagrams) {
  const auto dir = scratch_dir("stages_added");
  const auto r = run_fspm("stages " + kTree + " --at 1 --added -o " +
                          (dir / "last.treeb").string() + " --json --profile 0.25");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TreeGraph given = read_tree_file(kTree);
  const TreeGraph last = read_tree_file((dir / "last.treeb").string());
  ASSERT_EQ(last.size(), given.size());
  for (NodeId i = 0; i < given.size(); ++i) ASSERT_LT((last.end(i) - given.end(i)).norm(), 1e-9);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GE(j["added_branches"].get<int>(), 0);
  EXPECT_GT(j["crown_ratio"].get<double>(), 0.0);
  EXPECT_LE(j["crown_ratio"].get<double>(), 1.0);
  double leaves = 0.0, wood = 0.0;
  for (NodeId i = 0; i < given.size(); ++i) {
    leaves += given.kind(i) == OrganKind::kLeaf ? 1.0 : 0.0;
    if (given.kind(i) == OrganKind::kInternode) {
      wood += 3.141592653589793 * given.radius(i) * given.radius(i) * given.length(i);
    }
  }
  for (const char* method : {"stratified", "main_axis"}) {
    const auto& p = j["profile"][method];
    double l = 0.0, w = 0.0;
    for (const double v : p["leaves"]) l += v;
    for (const double v : p["wood_m3"]) w += v;
    EXPECT_NEAR(l, leaves, 1e-9) << method;
    EXPECT_NEAR(w, wood, 1e-9 * wood) << method;
    EXPECT_NEAR(p["tissue_above"][0].get<double>(), 1.0, 1e-12) << method;
  }
}

TEST(StagesCli, OneOfAtAndStepsIsRequired) {
  const auto dir = scratch_dir("stages_bad");
  const auto r = run_fspm("stages " + kTree + " --at 0.5 --steps 3 -o " + (dir / "x").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("either --at"), std::string::npos) << r.err;
  EXPECT_EQ(run_fspm("stages " + kTree + " --at 1.5 -o " + (dir / "y.tree").string()).exit_code, 1);
}

// A branch mesh written by `fspm mesh` is read through its skeleton (Pirk 5.2.1): the skeleton
// has the given tree's height and about its total internode length, and the last stage is the
// skeleton.
// A tree grown with the pipes of its shed branches kept gives --shed-branches something to read
// back; the last stage is still the given tree. A tree whose radii follow the pipe model gives
// nothing, and a warning that says how to keep them.
TEST(StagesCli, ShedBranchesFromKeptPipes) {
  const auto dir = scratch_dir("stages_shed");
  const std::string kept = (dir / "kept.treeb").string();
  auto r = run_fspm("grow --preset B --years 12 --set keep_shed_pipes=true -o " + kept);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("stages " + kept + " --at 1 --shed-branches --growth-profiles by_chain -o " +
               (dir / "last.treeb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_GT(nlohmann::json::parse(r.out)["shed_branches"].get<int>(), 0);
  const TreeGraph given = read_tree_file(kept);
  const TreeGraph last = read_tree_file((dir / "last.treeb").string());
  ASSERT_EQ(last.size(), given.size());
  for (NodeId i = 0; i < given.size(); ++i) {
    ASSERT_NEAR(last.radius(i), given.radius(i), 1e-9) << i;
  }
  r = run_fspm("stages " + kTree + " --at 0.5 --shed-branches -o " + (dir / "half.treeb").string() +
               " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["shed_branches"].get<int>(), 0);
  EXPECT_NE(r.err.find("keep_shed_pipes=true"), std::string::npos) << r.err;
  r = run_fspm("stages " + kTree + " --at 0.5 --growth-profiles linear -o " +
               (dir / "bad.treeb").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("by_chain"), std::string::npos) << r.err;
}

TEST(StagesCli, BranchMeshThroughItsSkeleton) {
  const auto dir = scratch_dir("stages_mesh");
  const std::string mesh = (dir / "tree.ply").string();
  auto r = run_fspm("mesh " + kTree + " -o " + mesh);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("stages " + mesh + " --at 1 -o " + (dir / "last.treeb").string() + " --skeleton " +
               (dir / "skeleton.treeb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["mesh"]["vertices"].get<int>(), 0);
  const TreeGraph given = read_tree_file(kTree);
  const TreeGraph skeleton = read_tree_file((dir / "skeleton.treeb").string());
  const auto extent = [](const TreeGraph& g, double* length) {
    double top = -1e9, bottom = 1e9;
    *length = 0.0;
    for (NodeId i = 0; i < g.size(); ++i) {
      if (g.kind(i) != OrganKind::kInternode) continue;
      top = std::max({top, g.start(i).z(), g.end(i).z()});
      bottom = std::min({bottom, g.start(i).z(), g.end(i).z()});
      *length += g.length(i);
    }
    return top - bottom;
  };
  double given_length = 0.0, skeleton_length = 0.0;
  const double given_height = extent(given, &given_length);
  EXPECT_NEAR(extent(skeleton, &skeleton_length), given_height, 0.02 * given_height);
  EXPECT_NEAR(skeleton_length, given_length, 0.05 * given_length);
  const TreeGraph last = read_tree_file((dir / "last.treeb").string());
  ASSERT_EQ(last.size(), skeleton.size());
  for (NodeId i = 0; i < last.size(); ++i) ASSERT_LT((last.end(i) - skeleton.end(i)).norm(), 1e-9);
}

// The same mesh as binary glTF (.glb, read through assimp): every vertex and triangle `fspm mesh`
// wrote comes back, and the skeleton has the given tree's height.
TEST(StagesCli, GlbBranchMeshThroughItsSkeleton) {
  const auto dir = scratch_dir("stages_glb");
  const std::string mesh = (dir / "tree.glb").string();
  auto r = run_fspm("mesh " + kTree + " -o " + mesh + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto written = nlohmann::json::parse(r.out);
  r = run_fspm("stages " + mesh + " --at 1 -o " + (dir / "last.treeb").string() + " --skeleton " +
               (dir / "skeleton.treeb").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mesh"]["vertices"], written["vertices"]);
  EXPECT_EQ(j["mesh"]["faces"], written["triangles"]);
  const auto height = [](const TreeGraph& g) {
    double top = -1e9, bottom = 1e9;
    for (NodeId i = 0; i < g.size(); ++i) {
      if (g.kind(i) != OrganKind::kInternode) continue;
      top = std::max({top, g.start(i).z(), g.end(i).z()});
      bottom = std::min({bottom, g.start(i).z(), g.end(i).z()});
    }
    return top - bottom;
  };
  const double given_height = height(read_tree_file(kTree));
  EXPECT_NEAR(height(read_tree_file((dir / "skeleton.treeb").string())), given_height,
              0.02 * given_height);
}

}  // namespace
}  // namespace fspm
