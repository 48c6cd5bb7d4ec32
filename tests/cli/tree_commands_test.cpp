#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

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
  write_text(dir / "bad.mtg", "MTG:\nENTITY-CODE\t\tLength\n/P1\n\t^/I1\t\t1\n");
  r = run_fspm("tree info " + (dir / "bad.mtg").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.mtg:4"), std::string::npos) << r.err;
}

// OpenAlea's MTG files (tests/data/mtg/openalea) all convert to trees with nodes.
TEST(TreeCli, EveryOpenAleaMtgConverts) {
  const auto dir = scratch_dir("mtg_suite");
  const std::filesystem::path suite = std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/openalea";
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(suite)) {
    if (entry.path().extension() != ".mtg") continue;
    ++files;
    const std::string out = (dir / (entry.path().stem().string() + ".tree")).string();
    const auto r = run_fspm("-q tree convert " + entry.path().string() + " " + out);
    ASSERT_EQ(r.exit_code, 0) << entry.path() << "\n" << r.err;
    const auto j = nlohmann::json::parse(run_fspm("tree info --json " + out).out);
    EXPECT_GT(j["nodes"].get<int>(), 0) << entry.path();
  }
  EXPECT_EQ(files, 21);
}

// A tree digitised in centimetres with diameters in millimetres: read in metres it is hundreds of
// metres tall and a warning names the option; with the units given its highest point stands
// above its first digitised shoot (S or U, the finest scale) by the difference of their ZZ
// coordinates (read here from the file) divided by 100.
TEST(TreeCli, MtgUnitsGiveTheTreeItsRealSize) {
  const auto dir = scratch_dir("mtg_units");
  const std::string mtg =
      std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/openalea/test8_boutdenoylum2.mtg";
  auto r = run_fspm("tree convert " + mtg + " " + (dir / "m.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--length-unit cm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--diameter-unit mm"), std::string::npos) << r.err;
  r = run_fspm("tree convert " + mtg + " " + (dir / "cm.tree").string() +
               " --length-unit cm --diameter-unit mm");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("--length-unit"), std::string::npos) << r.err;
  EXPECT_NE(read_text(dir / "cm.tree").find("lengths read in cm, diameters in mm"),
            std::string::npos);
  // ZZ is the 3rd feature column after the code columns of the ENTITY-CODE header.
  std::ifstream in(mtg);
  std::string line;
  double zfirst = 0.0, zmax = -1e300;
  bool first = true;
  std::size_t zz_cell = 0;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::size_t from = 0;
    for (std::size_t tab; (tab = line.find('\t', from)) != std::string::npos; from = tab + 1) {
      cells.push_back(line.substr(from, tab - from));
    }
    cells.push_back(line.substr(from));
    if (cells[0] == "ENTITY-CODE") {
      zz_cell = std::find(cells.begin(), cells.end(), "ZZ") - cells.begin();
    } else if (zz_cell > 0 && zz_cell < cells.size() && !cells[zz_cell].empty() &&
               cells[zz_cell].find_first_not_of(" \r") != std::string::npos) {
      const double z = std::stod(cells[zz_cell]);
      std::string cell;  // the code: the first non-empty cell
      for (const std::string& c : cells) {
        if (!c.empty()) {
          cell = c;
          break;
        }
      }
      const bool shoot = std::regex_search(cell, std::regex("[/<+^][SU][0-9]"));
      if (first && shoot) {
        zfirst = z;
        first = false;
      }
      zmax = std::max(zmax, z);
    }
  }
  ASSERT_GT(zmax, zfirst);
  const auto m =
      nlohmann::json::parse(run_fspm("tree info --json " + (dir / "m.tree").string()).out);
  const auto cm =
      nlohmann::json::parse(run_fspm("tree info --json " + (dir / "cm.tree").string()).out);
  EXPECT_NEAR(cm["height"].get<double>(), m["height"].get<double>() / 100.0, 1e-9);
  // Height is measured from the root's base, one median shoot below its digitised top (a few
  // centimetres).
  EXPECT_NEAR(cm["height"].get<double>(), (zmax - zfirst) / 100.0, 0.1);
}

// A topology-only MTG (no coordinates, lengths or diameters) becomes a plant drawn by the plant
// frame, every position and radius marked as inferred, and meshes into a non-empty surface.
TEST(TreeCli, TopologyOnlyMtgIsDrawnAndSaysWhatWasInferred) {
  const auto dir = scratch_dir("mtg_topology");
  const std::string mtg = std::string(FSPM_SOURCE_DIR) + "/tests/data/mtg/openalea/mtg4.mtg";
  auto r = run_fspm("tree info --json " + mtg);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["nodes"], 39);
  EXPECT_EQ(j["positions_inferred"], 39);
  EXPECT_EQ(j["radii_inferred"], 39);
  EXPECT_GT(j["height"].get<double>(), 0.5);
  EXPECT_GT(j["crown_width"].get<double>(), 0.1);
  r = run_fspm("mesh " + mtg + " -o " + (dir / "m.obj").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_text(dir / "m.obj").find("\nf "), std::string::npos);
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

// A feature name that is not UTF-8 (bytes of a Latin-1 file; found by fuzzing the MTG reader)
// is written as U+FFFD in text and JSON, not an internal error.
TEST(TreeCli, InfoWritesNamesThatAreNotUtf8) {
  const auto dir = scratch_dir("info_latin1");
  write_text(dir / "l.mtg",
             "#\n#\nCODE:\xb2-RO,A\nMTG:\nENTITY-CODE\t\t\xff\xff\xff\nENTN\n"
             "^/I0+.+knnnnnnPnnn2011\t2.");
  auto r = run_fspm("tree info " + (dir / "l.mtg").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\xef\xbf\xbd"), std::string::npos) << r.out;
  r = run_fspm("tree info --json " + (dir / "l.mtg").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NE(j["attributes"].dump(), "");
}

// The shipped Y of three tubes (rings, quads, no caps; its axes are written in its header): the
// skeleton has the trunk from the ground and two order-1 branches ending at (0.8, 0, 3.2) and
// (-0.6, 0.3, 3.0), so the bounding box and the counts are known in closed form.
TEST(TreeCli, TubeMeshConvertsToItsSkeleton) {
  const auto dir = scratch_dir("tubes");
  const std::string obj = std::string(FSPM_SOURCE_DIR) + "/examples/trees/y_tubes.obj";
  auto r = run_fspm("tree convert " + obj + " " + (dir / "y.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_fspm("tree info --json " + (dir / "y.tree").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["tips"], 2);
  EXPECT_EQ(j["max_order"], 1);
  const double lo[3] = {-0.6, 0.0, 0.0}, hi[3] = {0.8, 0.3, 3.2};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j["bbox_min"][k].get<double>(), lo[k], 0.05) << k;
    EXPECT_NEAR(j["bbox_max"][k].get<double>(), hi[k], 0.05) << k;
  }
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

// The canopy light per cluster and for the tree: the clusters' areas add up to the tree's, STAR is
// half the light interception efficiency, and a real sky (--sky) adds the absorbed PAR; --sky on a
// tree without leaf clusters is an error.
TEST(TreeCli, InfoJsonReportsTheCanopyLight) {
  const std::string open = std::string(FSPM_SOURCE_DIR) + "/examples/trees/open_a12.treeb";
  const auto dir = scratch_dir("info_canopy_light");
  write_text(dir / "sky.toml",
             "sky = { site = { latitude = 50, longitude = 8, elevation = 200, utc_offset = 1 }, "
             "date = \"2024-06-01\" }\n");
  const auto r = run_fspm("tree info --json --sky " + (dir / "sky.toml").string() + " " + open);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto c = nlohmann::json::parse(r.out)["canopy_light"];
  ASSERT_TRUE(c.is_object()) << r.out;
  EXPECT_EQ(c["sky"], "site");
  ASSERT_EQ(c["per_cluster"].size(), c["clusters"].get<std::size_t>());
  double sunlit = 0.0, absorbed = 0.0;
  for (const auto& k : c["per_cluster"]) {
    sunlit += k["sunlit_leaf_area_m2"].get<double>();
    absorbed += k["absorbed_par_mol_day"].get<double>();
    EXPECT_NEAR(k["star"].get<double>(), 0.5 * k["lie"].get<double>(), 1e-12);
  }
  EXPECT_NEAR(sunlit, c["sunlit_leaf_area_m2"].get<double>(), 1e-9 * sunlit);
  EXPECT_NEAR(absorbed, c["absorbed_par_mol_day"].get<double>(), 1e-9 * absorbed);
  EXPECT_GT(absorbed, 0.0);
  EXPECT_GT(c["lie"].get<double>(), 0.0);
  EXPECT_LT(c["lie"].get<double>(), 1.0);
  const auto plain = nlohmann::json::parse(run_fspm("tree info --json " + open).out);
  EXPECT_EQ(plain["canopy_light"]["sky"], "cos2");
  EXPECT_FALSE(plain["canopy_light"].contains("absorbed_par_mol_day"));
  write_text(dir / "x.nwk", "((1,2)3,4)5;\n");
  const auto bare =
      run_fspm("tree info --sky " + (dir / "sky.toml").string() + " " + (dir / "x.nwk").string());
  EXPECT_EQ(bare.exit_code, 1);
  EXPECT_NE(bare.err.find("leaf clusters"), std::string::npos) << bare.err;
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
  // The commit the build was configured from and the optional parts of the build.
  EXPECT_TRUE(std::regex_search(v.out, std::regex("\ncommit ([0-9a-f]{12}|unknown)\nfeatures:")))
      << v.out;
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
