// fspm report --html, run as a user would: the folder it writes and what data.js holds. The page
// itself is checked in a browser by scripts/html_report_check.sh.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

// Two points of an L-system sweep, two replicates each, trees kept; [report] html = true.
std::string sweep(const fs::path& dir) {
  const fs::path exp = dir / "e.toml";
  std::ofstream(exp) << "[experiment]\nname = \"h\"\nseed = 5\nreplicates = 2\n[model]\n"
                        "kind = \"lsystem\"\nfile = \""
                     << FSPM_SOURCE_DIR
                     << "/examples/lsystems/stochastic_plant.l\"\n[sweep]\nsteps = [2, 3]\n"
                        "[outputs]\nmetrics = [\"internodes\", \"height\"]\nkeep = [\"tree\"]\n"
                        "[report]\nrenders = 1\nhtml = true\n";
  const std::string out = (dir / "out").string();
  const CommandResult run = run_fspm("run " + exp.string() + " --jobs 2 --out " + out);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return out;
}

TEST(HtmlReport, WritesThePageItsLibrariesDataAndTrees) {
  const fs::path dir = scratch_dir("html_report");
  const std::string out = sweep(dir);
  const CommandResult report = run_fspm("report " + out + " --no-figures --json");
  if (report.err.find("browser files are missing") != std::string::npos) {
    GTEST_SKIP() << report.err;  // built without npm
  }
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const auto summary = nlohmann::json::parse(report.out);
  const fs::path page = dir / "out" / "report" / "index.html";
  EXPECT_EQ(summary["html"], page.string());
  EXPECT_NE(read_text(page).find("<script src=\"data.js\"></script>"), std::string::npos);
  for (const char* lib : {"three.min.js", "plotly.min.js", "marked.min.js", "report.js"}) {
    EXPECT_GT(fs::file_size(dir / "out" / "report" / "lib" / lib), 1000u) << lib;
  }
  const std::string data = read_text(dir / "out" / "report" / "data.js");
  const std::string prefix = "window.FSPM_REPORT = ";
  ASSERT_EQ(data.substr(0, prefix.size()), prefix);
  const auto d = nlohmann::json::parse(data.substr(prefix.size(), data.rfind(';') - prefix.size()));
  // The runs as the database has them (results export), seeds as text.
  const auto rows = nlohmann::json::parse(run_fspm("results export " + out + " --json").out);
  ASSERT_EQ(d["runs"]["run"].size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& row = rows["runs"][i];
    EXPECT_EQ(d["runs"]["run"][i], row["run"]);
    EXPECT_EQ(d["runs"]["seed"][i], std::to_string(row["seed"].get<std::uint64_t>()));
    EXPECT_EQ(d["runs"]["parameters"]["steps"][i], row.at("parameters").at("steps"));
    EXPECT_EQ(d["runs"]["metrics"]["internodes"][i], row.at("metrics").at("internodes"));
  }
  EXPECT_EQ(d["metrics"][1],
            nlohmann::json({{"name", "height"}, {"unit", "model units"}, {"timing", false}}));
  // renders = 1: one tree, a script that hands the page its .glb.
  ASSERT_EQ(d["trees"].size(), 1u);
  const std::string run = std::to_string(d["trees"][0]["run"].get<std::size_t>());
  const std::string stem = d["tree_files"].at(run);
  const std::string script = read_text(dir / "out" / "report" / "trees" / (stem + ".js"));
  EXPECT_EQ(script.substr(0, 10 + stem.size()), "fspmGlb(\"" + stem + "\"");
  EXPECT_NE(d["markdown"].get<std::string>().find("<div class=\"fspm-trees\"></div>"),
            std::string::npos);
  // An L-system tree has no leaf clusters: no light profile, no placeholder for it.
  EXPECT_EQ(d["light_profiles"], nlohmann::json::array());
  EXPECT_EQ(d["markdown"].get<std::string>().find("fspm-lightprofile"), std::string::npos);
}

// The light profile's numbers in data.js: the example tree adapted 7.5 m from a 6 m wall (run 0)
// and 1 m from it (run 1); the wall takes part of the near tree's sky.
TEST(HtmlReport, DataHoldsTheLightProfileOfEachTypicalTree) {
  const fs::path dir = scratch_dir("html_report_light");
  const std::string examples = std::string(FSPM_SOURCE_DIR) + "/examples";
  write_text(dir / "e.toml", "[experiment]\nname = \"w\"\n[model]\nkind = \"adapt\"\nfile = \"" +
                                 examples + "/trees/open_a12.treeb\"\nscene = \"" + examples +
                                 "/environment/wall_scene.json\"\n[sweep]\ntree_x_m = [-5.0, 1.5]\n"
                                 "[outputs]\nmetrics = [\"nodes\"]\n");
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_fspm("run " + (dir / "e.toml").string() + " -j 2 -o " + out).exit_code, 0);
  const CommandResult report = run_fspm("report " + out + " --no-figures --html");
  if (report.err.find("browser files are missing") != std::string::npos) {
    GTEST_SKIP() << report.err;  // built without npm
  }
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string data = read_text(dir / "out" / "report" / "data.js");
  const std::string prefix = "window.FSPM_REPORT = ";
  const auto d = nlohmann::json::parse(data.substr(prefix.size(), data.rfind(';') - prefix.size()));
  const std::string md = d["markdown"].get<std::string>();
  EXPECT_NE(md.find("## Light in the crown"), std::string::npos) << md;
  EXPECT_NE(md.find("<div class=\"fspm-lightprofile\"></div>"), std::string::npos) << md;
  EXPECT_NE(md.find("share of the open sky"), std::string::npos) << md;
  const auto& profiles = d["light_profiles"];
  ASSERT_EQ(profiles.size(), 2u) << profiles;
  double mean_light[2] = {0.0, 0.0};
  for (const auto& t : profiles) {
    const std::size_t run = t["run"].get<std::size_t>();
    ASSERT_LT(run, 2u);
    const std::size_t n = t["height_m"].size();
    ASSERT_GE(n, 2u);
    ASSERT_LE(n, 10u);
    ASSERT_EQ(t["mean_light"].size(), n);
    ASSERT_EQ(t["clusters"].size(), n);
    int clusters = 0;
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0) {
        EXPECT_GT(t["height_m"][k].get<double>(), t["height_m"][k - 1].get<double>());
      }
      const double light = t["mean_light"][k].get<double>();
      EXPECT_GE(light, 0.0);
      EXPECT_LE(light, 1.0);
      EXPECT_GT(t["clusters"][k].get<int>(), 0);
      clusters += t["clusters"][k].get<int>();
      mean_light[run] += light * t["clusters"][k].get<int>();
    }
    mean_light[run] /= clusters;
  }
  EXPECT_LT(mean_light[1], mean_light[0]);
}

TEST(HtmlReport, MissingBrowserFilesAreOneLineAndExitOne) {
  const fs::path dir = scratch_dir("html_report_missing");
  const std::string out = sweep(dir);
  const CommandResult report =
      run_fspm("report " + out + " --no-figures", "FSPM_REPORT_WEB_DIR=" + dir.string() + " ");
  EXPECT_EQ(report.exit_code, 1);
  EXPECT_NE(report.err.find("browser files are missing"), std::string::npos) << report.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "report" / "index.html"));
}

}  // namespace
}  // namespace fspm::testing
