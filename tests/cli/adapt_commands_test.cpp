// fspm adapt, run as a user would: grow a tree, adapt it to an empty scene and beside a wall.
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

TEST(AdaptCli, EmptySceneKeepsTheTreeAndAWallBendsItAway) {
  const auto dir = scratch_dir("adapt");
  std::ofstream(dir / "empty.json") << R"({"occluders": []})";
  // 1 m east: the wall cuts through the crown, whose branches there are pruned.
  std::ofstream(dir / "wall.json")
      << R"({"occluders": [{"type": "wall", "from": [1.0, -20], "to": [1.0, 20], "height": 20}]})";
  const auto tree = (dir / "a.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 10 -o " + tree).exit_code, 0);

  const auto e = run_fspm("adapt " + tree + " --scene " + (dir / "empty.json").string() + " -o " +
                          (dir / "e.tree").string() + " --json");
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const auto je = nlohmann::json::parse(e.out);
  EXPECT_EQ(je["pruned_nodes"], 0);
  EXPECT_LT(je["mean_tip_displacement"].get<double>(), 1e-9);
  EXPECT_EQ(je["nodes"].get<std::size_t>(), read_tree_file(tree).size());

  const auto w = run_fspm("adapt " + tree + " --scene " + (dir / "wall.json").string() + " -o " +
                          (dir / "w.tree").string() + " --json");
  ASSERT_EQ(w.exit_code, 0) << w.err;
  const auto jw = nlohmann::json::parse(w.out);
  EXPECT_LT(jw["mean_tip_shift"][0].get<double>(), 0.0);
  EXPECT_GT(jw["pruned_nodes"].get<int>(), 0);
  EXPECT_GE(jw["seconds"].get<double>(), 0.0);
  // By default the pruned branches are gone from the output.
  const std::size_t nodes = jw["nodes"].get<std::size_t>();
  const std::size_t pruned = jw["pruned_nodes"].get<std::size_t>();
  const TreeGraph adapted = read_tree_file((dir / "w.tree").string());
  EXPECT_EQ(adapted.size(), nodes - pruned);
  EXPECT_TRUE(adapted.has_attribute("displacement"));

  // --keep-pruned keeps them, flagged, and tree info counts them.
  const auto k = run_fspm("adapt " + tree + " --scene " + (dir / "wall.json").string() + " -o " +
                          (dir / "k.tree").string() + " --keep-pruned");
  ASSERT_EQ(k.exit_code, 0) << k.err;
  const TreeGraph kept = read_tree_file((dir / "k.tree").string());
  ASSERT_EQ(kept.size(), nodes);
  ASSERT_TRUE(kept.has_attribute("pruned"));
  std::size_t flagged = 0;
  for (double v : kept.attribute("pruned")) flagged += v != 0.0 ? 1 : 0;
  EXPECT_EQ(flagged, pruned);
  const auto info = run_fspm("tree info " + (dir / "k.tree").string() + " --json");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_EQ(nlohmann::json::parse(info.out)["pruned"].get<std::size_t>(), pruned);
  const auto text = run_fspm("tree info " + (dir / "k.tree").string());
  EXPECT_NE(text.out.find("pruned: " + std::to_string(pruned)), std::string::npos) << text.out;
  // A tree without the attribute says nothing about pruning.
  const auto plain = run_fspm("tree info " + tree + " --json");
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("pruned"));
  // Asking for both is a usage error.
  EXPECT_NE(run_fspm("adapt " + tree + " --scene " + (dir / "wall.json").string() + " -o " +
                     (dir / "x.tree").string() + " --keep-pruned --remove-pruned")
                .exit_code,
            0);

  // Several trees: -o is a directory and the JSON is a list; --remove-pruned (the default) is
  // still accepted.
  const auto m =
      run_fspm("adapt " + tree + " " + tree + " --scene " + (dir / "wall.json").string() + " -o " +
               (dir / "many").string() + " --json --remove-pruned");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const auto jm = nlohmann::json::parse(m.out);
  ASSERT_TRUE(jm.is_array());
  EXPECT_EQ(jm.size(), 2u);
  EXPECT_EQ(read_tree_file((dir / "many" / "a.tree").string()).size(),
            jw["nodes"].get<std::size_t>() - jw["pruned_nodes"].get<std::size_t>());
}

TEST(AdaptCli, SeveralScenesReadaptTheSameAnalysis) {
  // fspm adapt TREE --scene A --scene B -o DIR: one analysis, one adaptation per scene, written
  // to DIR/<scene>/<tree>; each result equals the single-scene run.
  const auto dir = scratch_dir("adapt_scenes");
  std::ofstream(dir / "empty.json") << R"({"occluders": []})";
  std::ofstream(dir / "wall.json")
      << R"({"occluders": [{"type": "wall", "from": [1.5, -20], "to": [1.5, 20], "height": 20}]})";
  const auto tree = (dir / "a.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 8 -o " + tree).exit_code, 0);
  const auto single = run_fspm("adapt " + tree + " --scene " + (dir / "wall.json").string() +
                               " -o " + (dir / "w.tree").string() + " --json");
  ASSERT_EQ(single.exit_code, 0) << single.err;
  const auto js = nlohmann::json::parse(single.out);

  const auto r =
      run_fspm("adapt " + tree + " --scene " + (dir / "empty.json").string() + " --scene " +
               (dir / "wall.json").string() + " -o " + (dir / "out").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_array());
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[0]["scene"], (dir / "empty.json").string());
  EXPECT_EQ(j[0]["pruned_nodes"], 0);
  EXPECT_EQ(j[1]["pruned_nodes"], js["pruned_nodes"]);
  EXPECT_DOUBLE_EQ(j[1]["mean_tip_displacement"].get<double>(),
                   js["mean_tip_displacement"].get<double>());
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "empty" / "a.tree"));
  EXPECT_EQ(read_tree_file((dir / "out" / "wall" / "a.tree").string()).size(),
            js["nodes"].get<std::size_t>() - js["pruned_nodes"].get<std::size_t>());
}

// Under a real sky (--sky) the adapted trees' leaf clusters carry their PAR, and a wall beside the
// tree takes part of it; without --sky there is none.
TEST(AdaptCli, RealSkyGivesTheLeavesTheirPar) {
  const auto dir = scratch_dir("adapt_sky");
  std::ofstream(dir / "empty.json") << R"({"occluders": []})";
  std::ofstream(dir / "wall.json")
      << R"({"occluders": [{"type": "wall", "from": [1.0, -20], "to": [1.0, 20], "height": 20}]})";
  std::ofstream(dir / "sky.toml") << "sky = { site = { latitude = 50, longitude = 8, elevation = "
                                     "200, utc_offset = 1 }, date = \"2024-06-01\" }\n";
  const auto tree = (dir / "a.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 10 -o " + tree).exit_code, 0);
  const auto adapt = [&](const char* scene, const char* out, bool sky) {
    return run_fspm("adapt " + tree + " --scene " + (dir / scene).string() + " -o " +
                    (dir / out).string() + " --json" +
                    (sky ? " --sky " + (dir / "sky.toml").string() : std::string()));
  };
  const auto e = adapt("empty.json", "e.tree", true);
  const auto w = adapt("wall.json", "w.tree", true);
  ASSERT_EQ(e.exit_code, 0) << e.err;
  ASSERT_EQ(w.exit_code, 0) << w.err;
  const double open = nlohmann::json::parse(e.out)["mean_leaf_par_umol_m2_s"].get<double>();
  const double walled = nlohmann::json::parse(w.out)["mean_leaf_par_umol_m2_s"].get<double>();
  EXPECT_GT(open, 0.0);
  EXPECT_LT(walled, open);
  const TreeGraph adapted = read_tree_file((dir / "e.tree").string());
  ASSERT_TRUE(adapted.has_attribute("par_umol_m2_s"));
  ASSERT_TRUE(adapted.has_attribute("daily_par_mol_m2"));
  const auto plain = adapt("empty.json", "p.tree", false);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_FALSE(nlohmann::json::parse(plain.out).contains("mean_leaf_par_umol_m2_s"));
}

TEST(AdaptCli, BadSceneIsAUserError) {
  const auto dir = scratch_dir("adapt_bad");
  const auto tree = (dir / "a.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 4 -o " + tree).exit_code, 0);
  const auto r = run_fspm("adapt " + tree + " --scene " + (dir / "missing.json").string() + " -o " +
                          (dir / "x.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace fspm

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;

TEST(AdaptCli, LightModelAndPruningRuleAreChosenOnTheCommandLine) {
  const auto dir = scratch_dir("adapt_models");
  std::ofstream(dir / "wall.json")
      << R"({"occluders": [{"type": "wall", "from": [1.5, -20], "to": [1.5, 20], "height": 20}]})";
  const auto tree = (dir / "a.tree").string();
  ASSERT_EQ(run_fspm("grow --preset A --years 10 -o " + tree).exit_code, 0);
  const std::string base =
      "adapt " + tree + " --scene " + (dir / "wall.json").string() + " --json -o ";
  const auto grid = run_fspm(base + (dir / "g.tree").string() + " --light-model shadow_grid");
  ASSERT_EQ(grid.exit_code, 0) << grid.err;
  const auto jg = nlohmann::json::parse(grid.out);
  EXPECT_LT(jg["mean_tip_shift"][0].get<double>(), 0.0);
  ASSERT_EQ(jg["pruned_centroid"].size(), 3u);
  const auto absolute = run_fspm(base + (dir / "a2.tree").string() + " --absolute-pruning");
  ASSERT_EQ(absolute.exit_code, 0) << absolute.err;
  const auto bad = run_fspm(base + (dir / "b.tree").string() + " --light-model sunny");
  EXPECT_EQ(bad.exit_code, 1);
  // Refused by the parser, naming the value and the choices.
  EXPECT_NE(bad.err.find("sunny"), std::string::npos) << bad.err;
  EXPECT_NE(bad.err.find("shadow_grid"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "b.tree"));
  // A model of growth only: the library's refusal, naming the use and adaptation's models.
  const auto growth_only =
      run_fspm(base + (dir / "c.tree").string() + " --light-model space_colonization");
  EXPECT_EQ(growth_only.exit_code, 1);
  EXPECT_NE(growth_only.err.find("light_model 'space_colonization' gives no light to leaf "
                                 "clusters (plastic adaptation): expected canopy, sky or "
                                 "shadow_grid"),
            std::string::npos)
      << growth_only.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "c.tree"));
}

}  // namespace
}  // namespace fspm
