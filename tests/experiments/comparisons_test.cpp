#include "experiments/comparisons.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <set>

#include "experiments/model_factory.hpp"
#include "experiments/report.hpp"
#include "experiments/results_db.hpp"
#include "experiments/runner.hpp"
#include "fspm/error.hpp"
#include "fspm/statistics.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

// Synthetic runs are chains of `nodes` internodes: with topological costs the distance between
// chains of m and n nodes is |m - n| (delete or insert the surplus, match the rest in order), the
// normalized distance |m - n| / (m + n) (deleting all of one and inserting all of the other).
const char* kChains =
    "[experiment]\nname = \"chains\"\nseed = 5\nreplicates = 6\n"
    "[model]\nkind = \"synthetic\"\n"
    "[sweep]\nlength = [1.0, 2.0]\nnodes = [3, 5]\n"
    "[distance]\ncost = \"topological\"\n"
    "[[comparison]]\nname = \"3-5\"\na = { nodes = 3 }\nb = { nodes = 5 }\nwithin = [\"length\"]\n"
    "pairs = 4\n"
    "[[comparison]]\nname = \"3-3\"\na = { nodes = 3 }\nb = { nodes = 3 }\nwithin = "
    "[\"length\"]\npairs = 4\n"
    "[[ttest]]\na = \"3-5\"\nb = \"3-3\"\n";

std::vector<RunRecord> run_all(const Experiment& x, const fs::path& out) {
  const auto model = make_model(x);
  RunnerOptions o;
  o.out_dir = out.string();
  o.jobs = 2;
  run_experiment(x, *model, o);
  return ResultsDb(out.string(), ResultsDb::Mode::kRead).read_all();
}

TEST(Comparisons, PairsWithoutReuseWithinGroupsAndExactDistances) {
  const auto dir = testing::scratch("cmp_pairs");
  const Experiment x = parse_experiment(kChains, "chains.toml");
  ASSERT_EQ(x.keep, std::vector<KeptFile>{KeptFile::kTree});  // comparisons keep the trees
  const std::vector<RunRecord> runs = run_all(x, dir / "out");
  ASSERT_EQ(runs.size(), 24u);
  const ComparisonResults c = run_comparisons(x, runs, (dir / "out").string(), 2);

  std::map<std::string, std::set<std::size_t>> used;  // per comparison and group
  std::map<std::string, std::size_t> count;
  for (const PairDistance& p : c.pairs) {
    const RunRecord& a = runs.at(p.run_a);
    const RunRecord& b = runs.at(p.run_b);
    const auto nodes = [](const RunRecord& r) {
      return parameter_integer(r.parameters.at("nodes"), "nodes");
    };
    const auto length = [](const RunRecord& r) {
      return parameter_number(r.parameters.at("length"), "length");
    };
    EXPECT_EQ(length(a), length(b)) << "pairs stay within their `within` group";
    EXPECT_EQ(p.group, "length=" + parameter_text(a.parameters.at("length")));
    EXPECT_EQ(p.seed_a, a.seed);
    EXPECT_EQ(p.seed_b, b.seed);
    if (p.comparison == "3-5") {
      EXPECT_EQ(nodes(a), 3);
      EXPECT_EQ(nodes(b), 5);
    } else {
      EXPECT_EQ(nodes(a), 3);
      EXPECT_EQ(nodes(b), 3);
    }
    EXPECT_DOUBLE_EQ(p.distance, std::abs(static_cast<double>(nodes(a) - nodes(b))));
    EXPECT_DOUBLE_EQ(p.normalized, p.distance / static_cast<double>(nodes(a) + nodes(b)));
    const std::string key = p.comparison + "/" + p.group;
    EXPECT_TRUE(used[key].insert(p.run_a).second) << "run used twice in " << key;
    EXPECT_TRUE(used[key].insert(p.run_b).second) << "run used twice in " << key;
    ++count[key];
  }
  // 6 runs per set and group: 4 pairs across sets, but only 3 within one set.
  EXPECT_EQ(count["3-5/length=1"], 4u);
  EXPECT_EQ(count["3-5/length=2"], 4u);
  EXPECT_EQ(count["3-3/length=1"], 3u);
  EXPECT_EQ(count["3-3/length=2"], 3u);
  EXPECT_EQ(c.notes.size(), 4u);  // 3-3 falls short twice; two undefined t-tests

  // One t-test per group, on the normalized distance by default; the 3-5 distances are all
  // 2 / 8, the 3-3 ones all 0: constant groups have no standard error, so t and p are undefined
  // (NaN) and a note says so.
  ASSERT_EQ(c.tests.size(), 2u);
  for (const TTestRow& t : c.tests) {
    EXPECT_EQ(t.scale, DistanceScale::kNormalized);
    EXPECT_DOUBLE_EQ(t.mean_a, 0.25);
    EXPECT_DOUBLE_EQ(t.mean_b, 0.0);
    EXPECT_EQ(t.n_a, 4u);
    EXPECT_EQ(t.n_b, 3u);
    EXPECT_TRUE(std::isnan(t.p));
    EXPECT_FALSE(t.significant());
  }
}

TEST(Comparisons, SameSeedSamePairsAndFilesRoundTrip) {
  const auto dir = testing::scratch("cmp_det");
  const Experiment x = parse_experiment(kChains, "chains.toml");
  const std::vector<RunRecord> runs = run_all(x, dir / "out");
  const ComparisonResults first = run_comparisons(x, runs, (dir / "out").string(), 1);
  const ComparisonResults second = run_comparisons(x, runs, (dir / "out").string(), 2);
  ASSERT_EQ(first.pairs.size(), second.pairs.size());
  for (std::size_t i = 0; i < first.pairs.size(); ++i) {
    EXPECT_EQ(first.pairs[i].run_a, second.pairs[i].run_a);
    EXPECT_EQ(first.pairs[i].run_b, second.pairs[i].run_b);
  }
  write_comparisons(first, (dir / "out").string());
  ComparisonResults back;
  ASSERT_TRUE(read_comparisons((dir / "out").string(), back));
  ASSERT_EQ(back.pairs.size(), first.pairs.size());
  EXPECT_EQ(back.pairs[0].seed_a, first.pairs[0].seed_a);
  std::ifstream csv(dir / "out" / kPairsFile);
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header,
            "comparison,group,run_a,run_b,seed_a,seed_b,distance,normalized_distance,nodes_a,"
            "nodes_b");
  EXPECT_DOUBLE_EQ(back.pairs[0].normalized, first.pairs[0].normalized);
  const std::string md = comparisons_markdown(x, back);
  EXPECT_NE(md.find("| length=1 | mean | 0.25 | 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| length=1 | mean raw distance | 2 | 0 |"), std::string::npos) << md;
  // p-values keep two significant digits down to 0.001.
  back.tests = comparison_ttests(x, back.pairs);
  ASSERT_FALSE(back.tests.empty());
  for (const auto& [p, text] : std::vector<std::pair<double, std::string>>{
           {0.0016, "p = 0.0016"}, {0.034, "p = 0.034"}, {0.27, "p = 0.27"}, {2e-5, "p < 0.001"}}) {
    back.tests[0].p = p;
    const std::string with_p = comparisons_markdown(x, back);
    EXPECT_NE(with_p.find(text), std::string::npos) << p << "\n" << with_p;
  }
}

// tested = "raw" in [distance]: the t-tests and the table compare the raw distance (2 and 0).
TEST(Comparisons, RawDistanceIsTestedWhenAsked) {
  const auto dir = testing::scratch("cmp_raw");
  std::string text = kChains;
  const std::string cost = "cost = \"topological\"\n";
  text.replace(text.find(cost), cost.size(), cost + "tested = \"raw\"\n");
  const Experiment x = parse_experiment(text, "chains.toml");
  EXPECT_EQ(x.distance.tested, DistanceScale::kRaw);
  const ComparisonResults c = run_comparisons(x, run_all(x, dir / "out"), (dir / "out").string());
  ASSERT_EQ(c.tests.size(), 2u);
  for (const TTestRow& t : c.tests) {
    EXPECT_EQ(t.scale, DistanceScale::kRaw);
    EXPECT_DOUBLE_EQ(t.mean_a, 2.0);
    EXPECT_DOUBLE_EQ(t.mean_b, 0.0);
  }
  const std::string md = comparisons_markdown(x, c);
  EXPECT_NE(md.find("| length=1 | mean | 2 | 0 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("mean raw distance"), std::string::npos) << md;
  text.replace(text.find("\"raw\""), 5, "\"rough\"");
  EXPECT_THROW(parse_experiment(text, "chains.toml"), ValueError);
}

TEST(Comparisons, SummaryTableGroupsRuns) {
  const auto dir = testing::scratch("cmp_table");
  const Experiment x = parse_experiment(
      "[experiment]\nname = \"t\"\nreplicates = 2\n[model]\nkind = \"synthetic\"\n"
      "[sweep]\nnodes = [2, 4]\nlength = [1.0, 3.0]\n"
      "[[table]]\ntitle = \"Heights\"\nwhere = { length = 3.0 }\nby = [\"nodes\"]\n"
      "metrics = [\"height\"]\n",
      "t.toml");
  const std::vector<RunRecord> runs = run_all(x, dir / "out");
  const std::string md = summary_tables_markdown(x, runs);
  // Chains of n internodes of length 3 are 3n high, identical across replicates.
  EXPECT_NE(md.find("| 2 | 2 | 6 ± 0 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 4 | 2 | 12 ± 0 |"), std::string::npos) << md;
  EXPECT_EQ(md.find("| 2 | 2 | 2 ± 0 |"), std::string::npos) << md;
}

TEST(Comparisons, DistanceToReferenceIsRecorded) {
  const auto dir = testing::scratch("cmp_ref");
  // The reference: a chain of 4 internodes, as Newick.
  testing::write(dir / "ref.nwk", "(((1)1)1)1;");
  const Experiment x = parse_experiment(
      "[experiment]\nname = \"r\"\n[model]\nkind = \"synthetic\"\n[sweep]\nnodes = [1, 4, 7]\n"
      "[outputs]\nmetrics = [\"nodes\", \"distance_to_reference\"]\nreference = \"ref.nwk\"\n"
      "[distance]\ncost = \"topological\"\n",
      (dir / "r.toml").string());
  const std::vector<RunRecord> runs = run_all(x, dir / "out");
  ASSERT_EQ(runs.size(), 3u);
  for (const RunRecord& r : runs) {
    const double n = r.metrics.at("nodes");
    EXPECT_DOUBLE_EQ(r.metrics.at("distance_to_reference"), std::abs(n - 4.0)) << n;
  }
}

TEST(Comparisons, BadSpecificationsNameKeyAndLine) {
  auto error = [](const std::string& body) {
    try {
      parse_experiment(
          "[experiment]\nname = \"e\"\n[model]\nkind = \"synthetic\"\n"
          "[sweep]\nnodes = [1, 2]\n" +
              body,
          "e.toml");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("[[comparison]]\nname = \"c\"\na = { set = \"T\" }\nb = { nodes = 1 }\n")
                .find("comparison.a.set: not a parameter"),
            std::string::npos);
  EXPECT_NE(error("[[comparison]]\nname = \"c\"\na = { nodes = 1 }\nb = { nodes = 2 }\n"
                  "[[ttest]]\na = \"c\"\nb = \"d\"\n")
                .find("e.toml:13"),
            std::string::npos);
  EXPECT_NE(error("[distance]\ncost = \"euclid\"\n").find("distance.cost"), std::string::npos);
  EXPECT_NE(error("[[table]]\nmetrics = [\"biomass\"]\n[outputs]\nmetrics = [\"nodes\"]\n")
                .find("not recorded"),
            std::string::npos);
  EXPECT_NE(error("[[comparison]]\nname = \"c\"\nb = { nodes = 2 }\n").find("comparison.a"),
            std::string::npos);
}

}  // namespace
}  // namespace fspm::experiments
