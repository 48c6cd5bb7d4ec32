// What a report tells its reader: the opening paragraphs, collapsed notes, plant metrics and
// timings apart, and the per-value statistics behind the plots against each swept parameter.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "experiments/experiment.hpp"
#include "experiments/report.hpp"
#include "experiments/report_findings.hpp"
#include "experiments/report_intro.hpp"
#include "experiments/report_notes.hpp"
#include "experiments/sweep_summary.hpp"

namespace fspm::experiments {
namespace {

TEST(ReportNotes, IdenticalNotesBecomeOneLineWithACount) {
  const std::vector<std::string> notes = {"tree missing", "other", "tree missing", "tree missing"};
  EXPECT_EQ(collapse_notes(notes), (std::vector<std::string>{"tree missing (3 times)", "other"}));
  EXPECT_EQ(notes_markdown(notes), "\nNote: tree missing (3 times)\n\nNote: other\n");
}

TEST(ReportNotes, NotesDifferingOnlyInTheirGroupBecomeOneLine) {
  std::vector<std::string> notes;
  for (const char* g : {"preset=A", "preset=B", "preset=C", "preset=D", "preset=E"}) {
    notes.push_back(std::string("comparison T-G (") + g + "): only 6 of 50 pairs");
  }
  notes.push_back("comparison G-G (preset=A): only 3 of 50 pairs");  // another text: its own line
  const std::vector<std::string> out = collapse_notes(notes);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0],
            "comparison T-G: only 6 of 50 pairs (5 times: preset=A; preset=B; preset=C; "
            "preset=D; ...)");
  EXPECT_EQ(out[1], "comparison G-G (preset=A): only 3 of 50 pairs");  // once: as it was
}

RunRecord run(std::size_t index, std::int64_t years, std::string set, double height, double seconds,
              RunStatus status = RunStatus::kOk) {
  RunRecord r;
  r.run = index;
  r.point = index;
  r.status = status;
  r.parameters = {{"years", years}, {"set", std::move(set)}};
  r.metrics = {{"height", height}, {"run_time", seconds}};
  return r;
}

TEST(ReportTables, PlantMetricsAndTimingsInSeparateTables) {
  ExperimentInfo info;
  info.name = "t";
  info.total_runs = 2;
  info.swept = {"years", "set"};
  info.metrics = {"height", "run_time"};
  const std::vector<RunRecord> runs{run(0, 10, "O", 2.0, 0.5), run(1, 20, "G", 4.0, 1.5)};
  const std::string md = markdown_report(info, runs);
  ASSERT_NE(md.find("## Metrics per parameter point"), std::string::npos) << md;
  EXPECT_NE(md.find("height (m)"), std::string::npos) << md;
  EXPECT_NE(md.find("## Marginal means over `years`"), std::string::npos) << md;
  EXPECT_EQ(md.find("run_time"), std::string::npos) << "timings come last, apart\n" << md;
  const std::string timing = timings_markdown(info, runs);
  ASSERT_NE(timing.find("## Timings per parameter point"), std::string::npos) << timing;
  EXPECT_NE(timing.find("| run_time (s) |"), std::string::npos) << timing;
  EXPECT_NE(timing.find("### Timings over `years`"), std::string::npos) << timing;
  EXPECT_EQ(timing.find("height"), std::string::npos) << timing;
  EXPECT_TRUE(is_timing_metric("grow_seconds"));
  EXPECT_FALSE(is_timing_metric("nodes"));
}

// With `years` swept, the means over another parameter are per age: set O at 10 years is the mean
// of its two runs there (2 and 4 m: 3), never pooled with the 20-year runs (which would give 11).
TEST(ReportTables, MarginalMeansOverOtherParametersArePerAge) {
  ExperimentInfo info;
  info.name = "t";
  info.total_runs = 6;
  info.swept = {"years", "set"};
  info.metrics = {"height"};
  const std::vector<RunRecord> runs{run(0, 10, "O", 2.0, 0.5),  run(1, 10, "O", 4.0, 0.5),
                                    run(2, 20, "O", 18.0, 0.5), run(3, 20, "O", 20.0, 0.5),
                                    run(4, 10, "G", 1.0, 0.5),  run(5, 20, "G", 9.0, 0.5)};
  const std::string md = markdown_report(info, runs);
  const std::size_t over_set = md.find("## Marginal means over `set`");
  ASSERT_NE(over_set, std::string::npos) << md;
  const std::string tables = md.substr(over_set);
  const std::size_t at10 = tables.find("### At years = 10");
  const std::size_t at20 = tables.find("### At years = 20");
  ASSERT_NE(at10, std::string::npos) << tables;
  ASSERT_NE(at20, std::string::npos) << tables;
  const std::string young = tables.substr(at10, at20 - at10);
  EXPECT_NE(young.find("| O | 3 ± 1.414 |"), std::string::npos) << young;
  EXPECT_NE(young.find("| G | 1 |"), std::string::npos) << young;
  EXPECT_NE(tables.substr(at20).find("| O | 19 ± 1.414 |"), std::string::npos) << tables;
  EXPECT_EQ(tables.find("| O | 11"), std::string::npos) << "pooled across ages\n" << tables;
  // Over `years` itself: one table, every run of each age.
  EXPECT_EQ(md.substr(0, over_set).find("### At years"), std::string::npos) << md;
}

// The statistics behind each plot: one entry per swept value (numbers ascending, text in order of
// first appearance) whose mean and sample standard deviation over the successful runs with that
// value match a direct computation over the rows.
TEST(SweepSummary, OneEntryPerValueWithTheMeanOfItsRuns) {
  ExperimentInfo info;
  info.swept = {"years", "set"};
  info.metrics = {"height", "run_time"};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 10.0);
  std::vector<RunRecord> runs;
  const std::int64_t years[] = {30, 10, 20};  // recorded out of order
  const char* sets[] = {"T", "O", "G"};
  for (std::size_t i = 0; i < 45; ++i) {
    runs.push_back(run(i, years[i % 3], sets[(i / 3) % 3], u(rng), u(rng),
                       i % 7 == 0 ? RunStatus::kError : RunStatus::kOk));
  }
  const std::vector<SweptParameter> summary = sweep_summary(info, runs);
  ASSERT_EQ(summary.size(), 2u);
  ASSERT_EQ(summary[0].values.size(), 3u);
  EXPECT_TRUE(summary[0].numeric());
  EXPECT_EQ(summary[0].values[0].text, "10");
  EXPECT_EQ(summary[0].values[2].number, 30.0);
  EXPECT_FALSE(summary[1].numeric());
  ASSERT_EQ(summary[1].values.size(), 3u);
  EXPECT_EQ(summary[1].values[0].text, "T");  // first seen
  for (const SweptParameter& p : summary) {
    for (const SweptValue& v : p.values) {
      // Two-pass mean and sample standard deviation over the matching successful rows.
      double sum = 0.0;
      std::size_t n = 0;
      for (const RunRecord& r : runs) {
        if (r.status == RunStatus::kOk && parameter_text(r.parameters.at(p.name)) == v.text) {
          sum += r.metrics.at("height");
          ++n;
        }
      }
      const double mean = sum / static_cast<double>(n);
      double squares = 0.0;
      for (const RunRecord& r : runs) {
        if (r.status == RunStatus::kOk && parameter_text(r.parameters.at(p.name)) == v.text) {
          squares += (r.metrics.at("height") - mean) * (r.metrics.at("height") - mean);
        }
      }
      const Moments& m = v.metrics.at("height");
      EXPECT_EQ(m.n, n) << p.name << " = " << v.text;
      EXPECT_NEAR(m.mean, mean, 1e-12) << p.name << " = " << v.text;
      EXPECT_NEAR(m.sd(), std::sqrt(squares / static_cast<double>(n - 1)), 1e-12);
    }
  }
}

// Counts 0, 0, 0, 12: mean 3, sample sd 6, so mean - sd = -3 lies below every count; the band
// is kept within [0, 12]: lower 0, upper 9.
TEST(ReportContents, SweepBandStaysWithinTheValues) {
  Moments m;
  for (const double x : {0.0, 0.0, 0.0, 12.0}) m.add(x);
  EXPECT_DOUBLE_EQ(m.mean, 3.0);
  EXPECT_DOUBLE_EQ(m.sd(), 6.0);
  EXPECT_DOUBLE_EQ(m.lower_band(), 0.0);
  EXPECT_DOUBLE_EQ(m.upper_band(), 9.0);
  Moments one;
  one.add(5.0);
  EXPECT_DOUBLE_EQ(one.lower_band(), 5.0);
  EXPECT_DOUBLE_EQ(one.upper_band(), 5.0);
}

const char* kGrowExperiment = R"(
[experiment]
name = "avg"
description = "adapted versus grown"
seed = 5
replicates = 4
[model]
kind = "grow"
[sweep]
years = [10, 20]
set = ["O", "G", "T"]
[outputs]
metrics = ["nodes", "height"]
[[comparison]]
name = "T-G"
a = { set = "T" }
b = { set = "G" }
within = ["years"]
pairs = 2
[[comparison]]
name = "G-G"
a = { set = "G" }
b = { set = "G" }
within = ["years"]
[[ttest]]
a = "T-G"
b = "G-G"
[report]
about = "Pirk found no difference."
)";

TEST(ReportIntroduction, SaysWhatWasRunAndWhatTheSetsAndGroupsMean) {
  const Experiment x = parse_experiment(kGrowExperiment);
  const std::string md = report_introduction(x);
  EXPECT_NE(md.find("adapted versus grown"), std::string::npos) << md;
  EXPECT_NE(md.find("24 runs"), std::string::npos) << md;  // 2 x 3 points x 4
  EXPECT_NE(md.find("years 10, 20 × set O, G, T"), std::string::npos) << md;
  for (const char* set : {"O", "G", "T"}) {
    EXPECT_NE(md.find(std::string("**") + set +
                      "**: " + std::string(grow_set_meaning(find_grow_set(set).value()))),
              std::string::npos)
        << set << "\n"
        << md;
  }
  EXPECT_NE(md.find("**T-G**: a run with set = T against one with set = G, both with the same "
                    "years (up to 2 pairs per group)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("**G-G**: two different runs with set = G"), std::string::npos) << md;
  EXPECT_NE(md.find("Are the T-G distances different from the G-G distances?"), std::string::npos)
      << md;
  EXPECT_NE(md.find("Pirk found no difference."), std::string::npos) << md;
}

// A synthetic result set with a known outcome. In both groups T-G has exactly the G-G values
// (t = 0, p = 1: like); in years=10 the T-O pairs are the T-T values plus 0.3 (a shift of many
// standard deviations: unlike, larger), in years=20 T-O equals T-T again (like).
std::vector<PairDistance> synthetic_pairs(std::size_t n) {
  std::vector<PairDistance> pairs;
  const auto add = [&](const char* comparison, const char* group, double shift) {
    for (std::size_t i = 0; i < n; ++i) {
      PairDistance p;
      p.comparison = comparison;
      p.group = group;
      p.normalized = 0.2 + 0.01 * static_cast<double>(i % 7) + shift;
      p.distance = 100.0 * p.normalized;
      pairs.push_back(p);
    }
  };
  for (const char* group : {"years=10", "years=20"}) {
    add("T-G", group, 0.0);
    add("G-G", group, 0.0);
    add("T-T", group, 0.0);
    add("T-O", group, std::string(group) == "years=10" ? 0.3 : 0.0);
  }
  return pairs;
}

Experiment four_comparisons() {
  std::string text = kGrowExperiment;
  text +=
      "[[comparison]]\nname = \"T-O\"\na = { set = \"T\" }\nb = { set = \"O\" }\n"
      "within = [\"years\"]\n"
      "[[comparison]]\nname = \"T-T\"\na = { set = \"T\" }\nb = { set = \"T\" }\n"
      "within = [\"years\"]\n"
      "[[ttest]]\na = \"T-O\"\nb = \"T-T\"\n";
  return parse_experiment(text);
}

TEST(ReportFindings, SayWhichComparisonsAreLikeAndWhichUnlike) {
  const Experiment x = four_comparisons();
  const std::vector<TTestRow> tests = comparison_ttests(x, synthetic_pairs(25));
  ASSERT_EQ(tests.size(), 4u);
  const std::string md = findings_markdown(x, tests);
  EXPECT_TRUE(md.starts_with("## Findings\n")) << md;
  EXPECT_NE(md.find("normalized constrained edit distance"), std::string::npos) << md;
  EXPECT_NE(md.find("Holm's correction over all 4 t-tests"), std::string::npos) << md;
  EXPECT_EQ(md.find("Warning"), std::string::npos) << md;  // 25 pairs per group
  // Identical samples: difference 0, d 0, p 1 and Holm p 1.
  EXPECT_NE(md.find("- **years=10**: T-G is **like** G-G: mean 0.2276 against 0.2276, difference "
                    "0 [95 % CI "),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("Cohen's d 0, p = 1, Holm p = 1 (25 and 25 pairs)"), std::string::npos) << md;
  // Shifted by 0.3: the difference is exactly 0.3.
  EXPECT_NE(md.find("T-O is **unlike** T-T (larger): mean 0.5276 against 0.2276, difference 0.3 "),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("- **years=20**: T-G is **like** G-G"), std::string::npos) << md;
  EXPECT_NE(md.find("In all, T-G is unlike G-G in 0 of 2 groups and like it in 2."),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("In all, T-O is unlike T-T in 1 of 2 groups (larger in 1, smaller in 0) and "
                    "like it in 1."),
            std::string::npos)
      << md;
  // Holm: the shifted test's p is tiny; every p_holm is at least its p.
  for (const TTestRow& t : tests) EXPECT_GE(t.p_holm, t.p);
}

TEST(ReportFindings, WarnWhenAGroupHasFewerThanTwentyPairs) {
  const Experiment x = four_comparisons();
  const std::string md = findings_markdown(x, comparison_ttests(x, synthetic_pairs(19)));
  EXPECT_NE(md.find("**Warning: some groups hold fewer than 20 pairs (the smallest 19).**"),
            std::string::npos)
      << md;
  EXPECT_TRUE(findings_markdown(x, {}).empty());
}

TEST(ReportFindings, EffectSizesOfAKnownDifference) {
  // a = {1, 2, 3}, b = {4, 5, 6}: difference -3, pooled sd 1, Cohen's d -3; Student's interval
  // -3 -+ t(0.975, 4) sqrt(2 / 3) = -3 -+ 2.776445 * 0.816497 (R: t.test(var.equal = TRUE)).
  Experiment x = four_comparisons();
  std::vector<PairDistance> pairs;
  for (double v : {1.0, 2.0, 3.0, 4.0, 5.0, 6.0}) {
    PairDistance p;
    p.comparison = v < 3.5 ? "T-G" : "G-G";
    p.group = "all";
    p.normalized = v;
    pairs.push_back(p);
  }
  const std::vector<TTestRow> tests = comparison_ttests(x, pairs);
  ASSERT_EQ(tests.size(), 1u);
  EXPECT_DOUBLE_EQ(tests[0].cohens_d, -3.0);
  EXPECT_NEAR(tests[0].difference_low, -3.0 - 2.776445 * 0.816497, 1e-5);
  EXPECT_NEAR(tests[0].difference_high, -3.0 + 2.776445 * 0.816497, 1e-5);
  EXPECT_DOUBLE_EQ(tests[0].p_holm, tests[0].p);  // a family of one
}

TEST(ReportIntroduction, OverriddenReplicatesSurviveTheStoredText) {
  Experiment x = parse_experiment(kGrowExperiment);
  override_replicates(x, 2);
  EXPECT_EQ(parse_experiment(x.text).replicates, 2u);
  EXPECT_EQ(parse_experiment(x.text).runs(), 12u);
}

}  // namespace
}  // namespace fspm::experiments
