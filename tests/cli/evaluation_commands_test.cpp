// fspm distance and fspm stats, run as a user would.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/cli/run_command.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::scratch_dir;
using testing::write_text;

// Hand-computed in tests/fspm/constrained_edit_distance_test.cpp (HandCaseNewickLabels): 203.
TEST(EvaluationCli, DistanceOfNewickStringsWithAbsoluteCost) {
  const auto r = run_fspm(
      "distance '(100,(200,300)1)1000;' '((100,200)2,300)1000;' --cost absolute --json --mapping");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["distance"], 203.0);
  EXPECT_EQ(j["nodes_a"], 5);
  EXPECT_EQ(j["nodes_b"], 5);
  ASSERT_EQ(j["mapping"].size(), 3u);
  EXPECT_EQ(j["mapping"][0], nlohmann::json::array({0, 0}));  // root to root
}

// A one-node tree against a root with one child: one insertion (topological), and with the
// absolute cost the inserted node's label.
TEST(EvaluationCli, OneNodeNewickLiteral) {
  auto r = run_fspm("distance '10;' '(1)10;' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 1.0);
  r = run_fspm("distance '10;' '(7)10;' --cost absolute --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 7.0);
}

// Taxon names and one-node literals; hand-computed in
// tests/fspm/constrained_edit_distance_test.cpp (HandCaseNamedNewickTopological): 3, and a named
// leaf against a named cherry is two insertions.
TEST(EvaluationCli, NamedNewickLiterals) {
  auto r = run_fspm("distance '((b,c)x,d)r;' \"('b',c,d)'r';\" --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 3.0);
  r = run_fspm("distance 'A;' '(A,B)C;' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 2.0);
  EXPECT_EQ(nlohmann::json::parse(r.out)["nodes_a"], 1);
  r = run_fspm("distance \"'Fagus sylvatica';\" 'A;' --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 0.0);
}

TEST(EvaluationCli, DistanceReadsNewickFilesAndDefaultsToTopological) {
  const auto dir = scratch_dir("distance");
  write_text(dir / "a.nwk", "((1,2)3,4)5;\n");
  write_text(dir / "b.nwk", "(1,2,4)5;\n");
  // Constrained: node 3's subtree cannot merge with 4's (see the hand case r(x(b,c),d)): 3.
  const auto r =
      run_fspm("distance --json " + (dir / "a.nwk").string() + " " + (dir / "b.nwk").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["distance"], 3.0);
  const auto s = run_fspm("distance '((1,2)3,4)5;' '((1,2)3,4)5;' --cost standardized --json");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_EQ(nlohmann::json::parse(s.out)["distance"], 0.0);
}

TEST(EvaluationCli, DistanceBadInputExitsOne) {
  auto r = run_fspm("distance '((1,2)3,4;' '(1,2)3;'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("Newick argument A"), std::string::npos) << r.err;
  r = run_fspm("distance '(1,2)3;' \"(1,'x)3;\"");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("Newick argument B"), std::string::npos) << r.err;
  r = run_fspm("distance '(1,2)3;' '(1,2)3;' --cost absolute --attr nope");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("nope"), std::string::npos) << r.err;
  r = run_fspm("distance '(1,2)3;' '(1,2)3;' --cost euclid");
  EXPECT_EQ(r.exit_code, 1);
}

// Student's sleep data; R: t.test(..., paired = TRUE) -> t = -4.0621, df = 9, p = 0.002833;
// Welch: t = -1.8608, df = 17.776, p = 0.07939.
TEST(EvaluationCli, TTestOnSleepData) {
  const auto dir = scratch_dir("ttest");
  write_text(dir / "a.txt", "0.7\n-1.6\n-0.2\n-1.2\n-0.1\n3.4\n3.7\n0.8\n0.0\n2.0\n");
  write_text(dir / "b.txt", "# group 2\n1.9\n0.8\n1.1\n0.1\n-0.1\n4.4\n5.5\n1.6\n4.6\n3.4\n\n");
  const std::string files = (dir / "a.txt").string() + " " + (dir / "b.txt").string();
  auto r = run_fspm("stats ttest --paired --json " + files);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["t"].get<double>(), -4.0621, 5e-5);
  EXPECT_EQ(j["df"], 9.0);
  EXPECT_NEAR(j["p"].get<double>(), 0.002833, 5e-7);
  EXPECT_EQ(j["n_a"], 10);
  EXPECT_NEAR(j["mean_b"].get<double>(), 2.33, 1e-12);
  r = run_fspm("stats ttest --welch --json " + files);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["df"].get<double>(), 17.776, 5e-4);
  EXPECT_NEAR(j["p"].get<double>(), 0.07939, 5e-6);
  r = run_fspm("stats ttest --welch --alternative less --json " + files);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(nlohmann::json::parse(r.out)["p"].get<double>(), 0.07939 / 2, 3e-6);
  EXPECT_EQ(run_fspm("stats ttest --welch --paired " + files).exit_code, 1);
}

// The text form rounds to four significant digits (R's values above, rounded by hand); --json
// keeps every digit.
TEST(EvaluationCli, TTestTextHasFourSignificantDigits) {
  const auto dir = scratch_dir("ttest_text");
  write_text(dir / "a.txt", "0.7\n-1.6\n-0.2\n-1.2\n-0.1\n3.4\n3.7\n0.8\n0.0\n2.0\n");
  write_text(dir / "b.txt", "1.9\n0.8\n1.1\n0.1\n-0.1\n4.4\n5.5\n1.6\n4.6\n3.4\n");
  const auto r =
      run_fspm("stats ttest --paired " + (dir / "a.txt").string() + " " + (dir / "b.txt").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  t: -4.062\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  p: 0.002833\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  mean_a: 0.75\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  mean_b: 2.33\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  df: 9\n"), std::string::npos) << r.out;
}

// Normalized: 203 / (1601 + 1602) by hand (tests/fspm/constrained_edit_distance_test.cpp).
TEST(EvaluationCli, DistanceShowsTheNormalizedDistance) {
  const std::string trees = "'(100,(200,300)1)1000;' '((100,200)2,300)1000;' --cost absolute";
  auto r = run_fspm("distance " + trees + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["normalized_distance"].get<double>(), 203.0 / 3203.0);
  EXPECT_EQ(j["deletion_cost_a"], 1601.0);
  EXPECT_EQ(j["insertion_cost_b"], 1602.0);
  r = run_fspm("distance " + trees);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("distance: 203\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("normalized_distance: 0.06338 "), std::string::npos) << r.out;
}

TEST(EvaluationCli, TTestReadsCsvColumn) {
  const auto dir = scratch_dir("ttest_csv");
  write_text(dir / "a.csv",
             "pair,distance\n1,0.7\n2,-1.6\n3,-0.2\n4,-1.2\n5,-0.1\n6,3.4\n7,3.7\n"
             "8,0.8\n9,0.0\n10,2.0\n");
  write_text(dir / "b.csv",
             "distance,pair\n1.9,1\n0.8,2\n1.1,3\n0.1,4\n-0.1,5\n4.4,6\n5.5,7\n"
             "1.6,8\n4.6,9\n3.4,10\n");
  const auto r = run_fspm("stats ttest --json --column distance " + (dir / "a.csv").string() + " " +
                          (dir / "b.csv").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["t"].get<double>(), -1.8608, 5e-5);  // Student, R var.equal = TRUE
  EXPECT_NEAR(j["p"].get<double>(), 0.07919, 5e-6);
}

TEST(EvaluationCli, StatsBadInputNamesFileAndLine) {
  const auto dir = scratch_dir("stats_bad");
  const auto good = (dir / "good.txt").string();
  write_text(dir / "good.txt", "1\n2\n3\n");
  write_text(dir / "empty.txt", "");
  write_text(dir / "text.txt", "1.5\n2.5\nabc\n");
  write_text(dir / "one.txt", "4.2\n");
  auto r = run_fspm("stats ttest " + (dir / "empty.txt").string() + " " + good);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find((dir / "empty.txt").string() + ":1"), std::string::npos) << r.err;
  r = run_fspm("stats ttest " + good + " " + (dir / "text.txt").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find((dir / "text.txt").string() + ":3:1"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("abc"), std::string::npos) << r.err;
  r = run_fspm("stats ttest " + good + " " + (dir / "one.txt").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find((dir / "one.txt").string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at least 2"), std::string::npos) << r.err;
  r = run_fspm("stats ttest " + good + " " + (dir / "missing.txt").string());
  EXPECT_EQ(r.exit_code, 1);
}

}  // namespace
}  // namespace fspm
