// fspm run with [[comparison]]s, fspm compare and fspm report, run as a user would.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "run_command.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

// Chains of 2 and 6 internodes (synthetic model): with topological costs every 2-6 pair is 4
// apart (delete or insert the surplus), every 2-2 pair 0; normalized, 4 / (2 + 6) = 0.5 and 0.
const char* kExperiment =
    "[experiment]\nname = \"chains\"\nseed = 3\nreplicates = 4\n[model]\nkind = \"synthetic\"\n"
    "[sweep]\nnodes = [2, 6]\n[distance]\ncost = \"topological\"\n"
    "[[comparison]]\nname = \"2-6\"\na = { nodes = 2 }\nb = { nodes = 6 }\n"
    "[[comparison]]\nname = \"2-2\"\na = { nodes = 2 }\nb = { nodes = 2 }\n"
    "[[ttest]]\na = \"2-6\"\nb = \"2-2\"\n";

TEST(ExperimentComparisons, RunComparesReportShowsAndCompareRecomputes) {
  const fs::path dir = scratch_dir("exp_cmp");
  write_text(dir / "chains.toml", kExperiment);
  const std::string out = (dir / "out").string();
  const CommandResult run = run_fspm("run " + (dir / "chains.toml").string() + " -j 2 -o " + out);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("6 pairs compared"), std::string::npos) << run.out;
  std::istringstream pairs(read_text(dir / "out" / "pairs.csv"));
  std::string line;
  std::getline(pairs, line);
  int rows = 0;
  while (std::getline(pairs, line)) {
    ++rows;
    const bool across = line.starts_with("2-6,");
    // distance is the 7th column, the normalized distance the 8th
    std::istringstream cells(line);
    std::string cell;
    for (int i = 0; i < 7; ++i) std::getline(cells, cell, ',');
    EXPECT_EQ(std::stod(cell), across ? 4.0 : 0.0) << line;
    std::getline(cells, cell, ',');
    EXPECT_EQ(std::stod(cell), across ? 0.5 : 0.0) << line;
  }
  EXPECT_EQ(rows, 6);  // 4 pairs across sets, 2 within (4 runs of nodes = 2)
  fs::remove(dir / "out" / "pairs.csv");
  const CommandResult cmp = run_fspm("compare " + out);
  ASSERT_EQ(cmp.exit_code, 0) << cmp.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "pairs.csv"));
  const CommandResult report = run_fspm("report " + out + " --no-figures");
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string md = read_text(dir / "out" / "report.md");
  EXPECT_NE(md.find("## Comparisons"), std::string::npos) << md;
  EXPECT_NE(md.find("| all | mean | 0.5 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| all | mean raw distance | 4 | 0 |"), std::string::npos) << md;
  // The text of compare rounds and names the distance tested.
  EXPECT_NE(cmp.out.find("t-test 2-6 vs 2-2 (all, normalized distance): t = "), std::string::npos)
      << cmp.out;
  // --json: the closed-form normalized distances (0.5 across, 0 within) in the t-test's means.
  const CommandResult json = run_fspm("compare " + out + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["pairs"], 6);
  ASSERT_EQ(j["ttests"].size(), 1u);
  EXPECT_EQ(j["ttests"][0]["a"], "2-6");
  EXPECT_EQ(j["ttests"][0]["distance"], "normalized");
  EXPECT_EQ(j["ttests"][0]["mean_a"], 0.5);
  EXPECT_EQ(j["ttests"][0]["mean_b"], 0.0);
  EXPECT_EQ(j["ttests"][0]["n_a"], 4);
  const CommandResult rj = run_fspm("report " + out + " --no-figures --json");
  ASSERT_EQ(rj.exit_code, 0) << rj.err;
  const auto r = nlohmann::json::parse(rj.out);
  EXPECT_EQ(r["runs"], 8);
  EXPECT_EQ(r["experiment"], true);
  EXPECT_EQ(r["figures"], false);
  EXPECT_EQ(r["report"], (dir / "out" / "report.md").string());
}

TEST(ExperimentComparisons, BadComparisonIsOneMessageBeforeAnyRun) {
  const fs::path dir = scratch_dir("exp_cmp_bad");
  write_text(dir / "bad.toml", std::string(kExperiment) + "[[ttest]]\na = \"2-6\"\nb = \"nope\"\n");
  const CommandResult run =
      run_fspm("run " + (dir / "bad.toml").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bad.toml:24"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("no [[comparison]] named 'nope'"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "results.sqlite"));
}

// The report with its figures, as a reader opens it: the opening paragraphs name the groups, the
// box plots say how many pairs each box holds, every recorded metric is plotted against the
// swept parameter, and the t-tests are summed up.
TEST(ExperimentComparisons, ReportExplainsAndPlots) {
  const fs::path dir = scratch_dir("exp_cmp_report");
  write_text(dir / "chains.toml", std::string(kExperiment) +
                                      "[outputs]\nmetrics = [\"nodes\", \"height\", "
                                      "\"run_time\"]\n[report]\nrenders = 0\n");
  const std::string out = (dir / "out").string();
  ASSERT_EQ(run_fspm("run " + (dir / "chains.toml").string() + " -j 2 -o " + out).exit_code, 0);
  const CommandResult report = run_fspm("report " + out);
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const std::string md = read_text(dir / "out" / "report.md");
  if (md.find("Note: figures left out") != std::string::npos) {
    GTEST_SKIP() << "no figures (no VTK or no display): " << md;
  }
  EXPECT_NE(md.find("**What was run.** 8 runs of the synthetic model"), std::string::npos) << md;
  EXPECT_NE(md.find("**2-6**: a run with nodes = 2 against one with nodes = 6."), std::string::npos)
      << md;
  EXPECT_NE(md.find("**2-2**: two different runs with nodes = 2."), std::string::npos) << md;
  // 4 runs per chain length: 4 pairs across, 2 without reuse within.
  EXPECT_NE(md.find("![distances, all: 2-6 (n = 4), 2-2 (n = 2)](figures/comparisons_0.png)"),
            std::string::npos)
      << md;
  EXPECT_TRUE(fs::exists(dir / "out" / "figures" / "comparisons_0.png"));
  // One plot per metric against `nodes` (two values: a line), PNGs on disk.
  EXPECT_NE(md.find("### Against `nodes`\n\nSuccessful runs per value (2: 4, 6: 4)."),
            std::string::npos)
      << md;
  for (const char* metric : {"nodes", "height", "run_time"}) {
    const std::string file = std::string("figures/sweep-0-") + metric + ".png";
    EXPECT_NE(md.find("](" + file + ")"), std::string::npos) << metric << "\n" << md;
    EXPECT_EQ(read_text(dir / "out" / file).substr(1, 3), "PNG") << file;
  }
  // Constant distances within each comparison: the t-test is undefined; the findings say so
  // for the single group, and a warning that 4 and 2 pairs are too few.
  EXPECT_NE(md.find("In all, 2-6 is unlike 2-2 in 0 of 1 group and like it in 0; not testable "
                    "in 1."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("**Warning: some groups hold fewer than 20 pairs (the smallest 2).**"),
            std::string::npos)
      << md;
  // Findings and comparisons first, then the metrics.
  EXPECT_LT(md.find("## Findings"), md.find("## Comparisons")) << md;
  EXPECT_LT(md.find("## Comparisons"), md.find("## Metrics per parameter point")) << md;
}

}  // namespace
}  // namespace fspm::testing
