#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;
using testing::write_text;

TEST(TreeCli, NewickSurvivesConversionThroughEveryFormat) {
  const auto dir = scratch_dir("convert");
  const std::string nwk = "((1,2)3,(4.5,(5,0.006)7)8)9;";
  write_text(dir / "x.nwk", nwk + "\n");
  auto r = run_fspm("tree convert " + (dir / "x.nwk").string() + " " + (dir / "x.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("tree convert " + (dir / "x.tree").string() + " " + (dir / "x.treeb").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("tree convert " + (dir / "x.treeb").string() + " " + (dir / "y.nwk").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir / "y.nwk"), nwk + "\n");
  r = run_fspm("tree convert " + (dir / "x.tree").string() + " " + (dir / "x.mtg").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_text(dir / "x.mtg").find("MTG:"), std::string::npos);
}

// Node names (taxon names, quoted labels) survive a Newick-to-Newick conversion; a format without
// names says how many it leaves behind.
TEST(TreeCli, ConversionKeepsNewickNamesOrSaysTheyAreDropped) {
  const auto dir = scratch_dir("convert_names");
  const std::string nwk = "((A:1,B:2)C:0.5,'Quercus robur':1,7);";
  write_text(dir / "x.nwk", nwk + "\n");
  auto r = run_fspm("tree convert " + (dir / "x.nwk").string() + " " + (dir / "y.nwk").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(dir / "y.nwk"), nwk + "\n");
  EXPECT_EQ(r.err.find("not kept"), std::string::npos) << r.err;
  r = run_fspm("tree convert " + (dir / "x.nwk").string() + " " + (dir / "x.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("4 node names are not kept"), std::string::npos) << r.err;
  r = run_fspm("-q tree convert " + (dir / "x.tree").string() + " " + (dir / "z.nwk").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(read_text(dir / "z.nwk"), "((:1,:2):0.5,:1,7);\n");
}

// A grown tree through MTG and back: every summary figure is the same (MTG carries the node
// ends, lengths, radii, birth times, orders and attributes; node numbering is depth first).
TEST(TreeCli, GrownTreeSurvivesMtgExportAndImport) {
  const auto dir = scratch_dir("mtg");
  const std::string open = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  auto r = run_fspm("tree convert " + open + " " + (dir / "t.mtg").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("tree convert " + (dir / "t.mtg").string() + " " + (dir / "back.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto a = nlohmann::json::parse(run_fspm("tree info --json " + open).out);
  const auto b =
      nlohmann::json::parse(run_fspm("tree info --json " + (dir / "back.tree").string()).out);
  for (const char* key : {"nodes", "internodes", "leaves", "tips", "max_order", "max_depth"}) {
    EXPECT_EQ(a[key], b[key]) << key;
  }
  EXPECT_DOUBLE_EQ(a["height"].get<double>(), b["height"].get<double>());
  EXPECT_NEAR(a["total_length"].get<double>(), b["total_length"].get<double>(), 1e-9);
  write_text(dir / "bad.mtg", "MTG:\nENTITY-CODE\t\tLength\n/P1\n^/I1\t\tten\n");
  r = run_fspm("tree info " + (dir / "bad.mtg").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.mtg:4"), std::string::npos) << r.err;
}

TEST(TreeCli, InfoJsonCountsNodes) {
  const auto dir = scratch_dir("info");
  write_text(dir / "x.nwk", "((1,2)3,(4,(5,6)7)8)9;\n");
  const auto r = run_fspm("tree info --json " + (dir / "x.nwk").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nodes"], 9);
  EXPECT_EQ(j["tips"], 5);
  EXPECT_EQ(j["max_depth"], 3);
}

// A grown tree's leaf clusters: the canopy summary adds up (sunlit + shaded = leaf area, sunlit =
// silhouette / 0.5) and the crown shades itself (STAR below the 0.5 of leaves in the open); a
// tree without clusters has none.
TEST(TreeCli, InfoJsonReportsTheCanopy) {
  const std::string open = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  const auto r = run_fspm("tree info --json " + open);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto c = nlohmann::json::parse(r.out)["canopy"];
  ASSERT_TRUE(c.is_object()) << r.out;
  EXPECT_GT(c["clusters"].get<int>(), 10);
  const double area = c["leaf_area_m2"].get<double>();
  EXPECT_NEAR(c["sunlit_leaf_area_m2"].get<double>() + c["shaded_leaf_area_m2"].get<double>(), area,
              1e-9 * area);
  EXPECT_NEAR(c["sunlit_leaf_area_m2"].get<double>(), c["silhouette_area_m2"].get<double>() / 0.5,
              1e-9 * area);
  EXPECT_GT(c["star"].get<double>(), 0.0);
  EXPECT_LT(c["star"].get<double>(), 0.5);
  const auto dir = scratch_dir("info_canopy");
  write_text(dir / "x.nwk", "((1,2)3,4)5;\n");
  EXPECT_FALSE(nlohmann::json::parse(run_fspm("tree info --json " + (dir / "x.nwk").string()).out)
                   .contains("canopy"));
}

TEST(TreeCli, MalformedFileExitsOneWithFileAndLine) {
  const auto dir = scratch_dir("bad");
  const auto bad = dir / "bad.tree";
  write_text(bad, "fspm-tree 1\nnodes 2\n0 - internode 1 0 0 0 0 0 0 1 0 0 1 1 0.1 0\noops\n");
  auto r = run_fspm("tree info " + bad.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(bad.string() + ":4"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());

  write_text(dir / "bad.nwk", "((1,2)3,(4;\n");
  r = run_fspm("tree convert " + (dir / "bad.nwk").string() + " " + (dir / "out.tree").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.nwk:1:"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.tree"));
}

TEST(TreeCli, UsageErrorsExitOneAndHelpExitsZero) {
  EXPECT_EQ(run_fspm("--help").exit_code, 0);
  EXPECT_EQ(run_fspm("tree info --help").exit_code, 0);
  const auto v = run_fspm("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.out.find("fspm "), std::string::npos);
  EXPECT_EQ(run_fspm("tree info").exit_code, 1);
  EXPECT_EQ(run_fspm("no-such-command").exit_code, 1);
  EXPECT_EQ(run_fspm("tree info /no/such/file.tree").exit_code, 1);
  EXPECT_EQ(run_fspm("tree convert a.nwk b.xyz").exit_code, 1);
}

}  // namespace
}  // namespace fspm

namespace fspm {
namespace {

TEST(GlobalOptions, QuietAndVerboseWorkBeforeAndAfterTheSubcommand) {
  const auto dir = testing::scratch_dir("global_options");
  const std::string tree = (dir / "a.tree").string();
  const auto after = testing::run_fspm("grow --preset A --years 3 -o " + tree + " -q");
  ASSERT_EQ(after.exit_code, 0) << after.err;
  EXPECT_EQ(after.err.find("[info]"), std::string::npos) << after.err;
  const auto before = testing::run_fspm("-q grow --preset A --years 3 -o " + tree);
  ASSERT_EQ(before.exit_code, 0) << before.err;
  EXPECT_EQ(before.err.find("[info]"), std::string::npos) << before.err;
  const auto loud = testing::run_fspm("grow --preset A --years 3 -o " + tree);
  EXPECT_NE(loud.err.find("[info]"), std::string::npos) << loud.err;
  EXPECT_EQ(testing::run_fspm("grow --preset A --years 3 -o " + tree + " --bogus").exit_code, 1);
}

}  // namespace
}  // namespace fspm
