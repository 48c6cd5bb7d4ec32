#include "experiments/render_selection.hpp"

#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

Experiment experiment(const std::string& report) {
  return parse_experiment(
      "[experiment]\nname = \"r\"\nseed = 8\n[model]\nkind = \"synthetic\"\n"
      "[sweep]\n\"x.g\" = [\"a\", \"b\", \"c\", \"d\", \"e\"]\nnodes = [5, 1, 3, 9]\n"
      "[outputs]\nmetrics = [\"height\", \"nodes\"]\n" +
          report,
      "r.toml");
}

// Runs in grid order: x.g slowest, nodes fastest; height = nodes (unit chains).
std::vector<RunRecord> records(const Experiment& x) {
  std::vector<RunRecord> runs;
  const std::vector<std::string> groups = {"a", "b", "c", "d", "e"};
  const std::vector<std::int64_t> nodes = {5, 1, 3, 9};
  for (std::size_t i = 0; i < x.runs(); ++i) {
    RunRecord r;
    r.run = i;
    r.point = i;
    r.seed = 100 + i;
    r.parameters = {{"x.g", groups[i / 4]}, {"nodes", nodes[i % 4]}};
    r.metrics = {{"height", static_cast<double>(nodes[i % 4])},
                 {"nodes", static_cast<double>(nodes[i % 4])}};
    runs.push_back(r);
  }
  return runs;
}

TEST(RenderSelection, TheMedianRunOfEachGroup) {
  const Experiment x = experiment("[report]\nrender_by = [\"x.g\"]\nrenders = 10\n");
  const auto choices = select_renders(x, records(x));
  ASSERT_EQ(choices.size(), 5u);
  // Heights 5, 1, 3, 9 sorted: 1, 3, 5, 9; the lower median is 3, the third run of each group.
  for (std::size_t g = 0; g < 5; ++g) EXPECT_EQ(choices[g].run, 4 * g + 2);
  EXPECT_EQ(choices[1].group, "x.g = b");
  EXPECT_NE(choices[1].caption.find("Run 6 (seed 106): x.g = b, nodes = 3"), std::string::npos)
      << choices[1].caption;
  EXPECT_NE(choices[1].caption.find("height = 3, the median of 4 runs with x.g = b"),
            std::string::npos)
      << choices[1].caption;
}

TEST(RenderSelection, AtMostRendersGroupsSpreadEvenly) {
  const Experiment x = experiment("[report]\nrender_by = [\"x.g\"]\nrenders = 2\n");
  const auto choices = select_renders(x, records(x));
  ASSERT_EQ(choices.size(), 2u);
  EXPECT_EQ(choices[0].group, "x.g = a");  // the first and the last group
  EXPECT_EQ(choices[1].group, "x.g = e");
  const Experiment three = experiment("[report]\nrender_by = [\"x.g\"]\nrenders = 3\n");
  const auto middle = select_renders(three, records(three));
  ASSERT_EQ(middle.size(), 3u);
  EXPECT_EQ(middle[1].group, "x.g = c");  // round(1 * 4 / 2) = 2
}

TEST(RenderSelection, DefaultsAreSixPointsByTheFirstMetric) {
  const Experiment x = experiment("");
  const auto choices = select_renders(x, records(x));
  // 20 points, one run each: groups round(i * 19 / 5) = 0, 4, 8, 11, 15, 19.
  ASSERT_EQ(choices.size(), 6u);
  const std::vector<std::size_t> expected = {0, 4, 8, 11, 15, 19};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(choices[i].run, expected[i]);
}

TEST(RenderSelection, WhereFailedRunsAndMetricChoice) {
  const Experiment x = experiment(
      "[report]\nrender_by = []\nrender_where = { \"x.g\" = \"b\" }\nrender_metric = \"nodes\"\n");
  std::vector<RunRecord> runs = records(x);
  runs[6].status = RunStatus::kError;  // the median run (nodes 3) failed
  const auto choices = select_renders(x, runs);
  ASSERT_EQ(choices.size(), 1u);
  EXPECT_EQ(choices[0].group, "all runs");
  // Remaining nodes of group b: 5, 1, 9 -> median 5, run 4.
  EXPECT_EQ(choices[0].run, 4u);
  EXPECT_TRUE(select_renders(experiment("[report]\nrenders = 0\n"), runs).empty());
}

TEST(RenderSelection, BadReportKeysNameTheirLine) {
  EXPECT_THROW(experiment("[report]\nrender_by = [\"colour\"]\n"), ValueError);
  EXPECT_THROW(experiment("[report]\nrender_metric = \"leaf_area\"\n"), ValueError);
  EXPECT_THROW(experiment("[report]\nrenders = -1\n"), ValueError);
  EXPECT_THROW(experiment("[report]\nrender = 2\n"), ValueError);
}

TEST(RenderSelection, ReportHtmlIsTrueOrFalse) {
  EXPECT_FALSE(experiment("").report_html);
  EXPECT_TRUE(experiment("[report]\nhtml = true\n").report_html);
  EXPECT_FALSE(experiment("[report]\nhtml = false\n").report_html);
  EXPECT_THROW(experiment("[report]\nhtml = 1\n"), ValueError);
}

TEST(RenderSelection, TheTreeComesFromTheKeptFileElseFromTheModel) {
  const auto dir = testing::scratch("render_tree");
  const Experiment x = experiment("");
  RunRecord r = records(x)[3];  // nodes = 9
  // Not kept: the synthetic model is run again with the recorded parameters.
  EXPECT_EQ(recorded_run_tree(x, r, dir.string()).size(), 9u);
  // Kept: the file is read (here a different tree, to tell them apart).
  TreeGraph two;
  NodeData d;
  d.end = Eigen::Vector3d(0, 0, 1);
  two.add_node(two.add_node(kNoNode, d), d);
  fs::create_directories(dir / "runs");
  write_tree_file(two, (dir / "runs/run-0000003.tree").string());
  r.files = {"runs/run-0000003.tree"};
  EXPECT_EQ(recorded_run_tree(x, r, dir.string()).size(), 2u);
}

// The obstacles drawn with a tree: the run's scene for grow sets G and T (not O, not "open"), and
// for the adapt model moved as the model moves it (by -tree_x_m, -tree_y_m).
TEST(RenderSelection, TheSceneOfARecordedRun) {
  const auto dir = testing::scratch("render_scene");
  testing::write(dir / "wall.json",
                 R"({"occluders": [{"type": "wall", "from": [2, -5], "to": [2, 5], "height": 3,
                     "thickness": 0.2}]})");
  const std::string file = (dir / "e.toml").string();
  const Experiment grow = parse_experiment(
      "[experiment]\nname = \"g\"\n[model]\nkind = \"grow\"\nscene = \"wall.json\"\n"
      "[sweep]\nset = [\"O\", \"G\", \"T\"]\n",
      file);
  RunRecord r;
  r.parameters = {{"set", std::string("O")}};
  EXPECT_FALSE(recorded_run_scene(grow, r).has_value());
  for (const char* set : {"G", "T"}) {
    r.parameters = {{"set", std::string(set)}};
    const auto scene = recorded_run_scene(grow, r);
    ASSERT_TRUE(scene.has_value()) << set;
    ASSERT_EQ(scene->boxes.size(), 1u);
    EXPECT_NEAR(scene->boxes[0].center.x(), 2.0, 1e-12);
  }
  r.parameters = {{"set", std::string("G")}, {"scene", std::string("open")}};
  EXPECT_FALSE(recorded_run_scene(grow, r).has_value());

  TreeGraph tree;
  NodeData d;
  d.end = Eigen::Vector3d(0, 0, 1);
  tree.add_node(kNoNode, d);
  write_tree_file(tree, (dir / "t.tree").string());
  const Experiment adapt = parse_experiment(
      "[experiment]\nname = \"a\"\n[model]\nkind = \"adapt\"\nfile = \"t.tree\"\n"
      "[sweep]\ntree_x_m = [1.5]\ntree_y_m = [-1.0]\nscene = [\"wall.json\"]\n",
      file);
  r.parameters = {{"tree_x_m", 1.5}, {"tree_y_m", -1.0}, {"scene", std::string("wall.json")}};
  const auto moved = recorded_run_scene(adapt, r);
  ASSERT_TRUE(moved.has_value());
  ASSERT_EQ(moved->boxes.size(), 1u);
  EXPECT_NEAR(moved->boxes[0].center.x(), 0.5, 1e-12);
  EXPECT_NEAR(moved->boxes[0].center.y(), 1.0, 1e-12);
  EXPECT_FALSE(recorded_run_scene(experiment(""), records(experiment(""))[0]).has_value());
}

}  // namespace
}  // namespace fspm::experiments
