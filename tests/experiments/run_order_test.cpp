#include "experiments/run_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>

#include "experiments/grow_model.hpp"
#include "experiments/lsystem_model.hpp"
#include "experiments/model_factory.hpp"
#include "experiments/results_db.hpp"
#include "experiments/runner.hpp"
#include "experiments/synthetic_model.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

Experiment synthetic(const std::string& body, int replicates) {
  return parse_experiment(
      "[experiment]\nname = \"o\"\nseed = 5\nreplicates = " + std::to_string(replicates) +
          "\n[model]\nkind = \"synthetic\"\n" + body,
      "o.toml");
}

// The synthetic model, remembering the order in which its runs start; the cost of a run is its
// free parameter x.cost.
class RecordingModel final : public Model {
 public:
  void check_parameter(const std::string& name, const ParameterValue& value) const override {
    inner_->check_parameter(name, value);
  }
  double cost_estimate(const ParameterSet& p) const override {
    return parameter_number(p.at("x.cost"), "x.cost");
  }
  RunResult run(const ParameterSet& p, std::uint64_t seed,
                const RunContext& context) const override {
    {
      const std::lock_guard lock(mutex_);
      started_.push_back(parameter_number(p.at("x.cost"), "x.cost"));
    }
    return inner_->run(p, seed, context);
  }
  std::vector<double> started() const { return started_; }

 private:
  std::unique_ptr<Model> inner_ = make_synthetic_model();
  mutable std::mutex mutex_;
  mutable std::vector<double> started_;
};

TEST(RunOrder, LongestFirstSortsByDescendingEstimateStableByIndex) {
  // Costs per point: 1, 5, 2, 5, 0; two replicates each (runs 2p and 2p + 1).
  const Experiment x = synthetic("[sweep]\n\"x.cost\" = [1, 5, 2, 5, 0]\n", 2);
  const RunPlan plan(x);
  const RecordingModel model;
  std::vector<std::size_t> pending(plan.size());
  for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = i;
  const std::vector<std::size_t> order = longest_first(plan, model, pending);
  const std::vector<std::size_t> expected = {2, 3, 6, 7, 4, 5, 0, 1, 8, 9};
  EXPECT_EQ(order, expected);
  // A subset (resume) keeps exactly its runs.
  EXPECT_EQ(longest_first(plan, model, {9, 0, 4, 7}), (std::vector<std::size_t>{7, 4, 0, 9}));
}

// A sweep of more than kLongestFirstLimit runs starts at once in grid order (no estimates).
TEST(RunOrder, HugeSweepsKeepGridOrder) {
  const Experiment x =
      synthetic("[sweep]\n\"x.cost\" = [1, 5]\n", static_cast<int>(kLongestFirstLimit / 2 + 1));
  const RunPlan plan(x);
  ASSERT_GT(plan.size(), kLongestFirstLimit);
  const RecordingModel model;
  std::vector<std::size_t> pending(plan.size());
  for (std::size_t i = 0; i < pending.size(); ++i) pending[i] = i;
  const std::vector<std::size_t> order = longest_first(plan, model, pending);
  EXPECT_EQ(order, pending);
}

TEST(RunOrder, TheRunnerStartsTheCostliestRunsFirstAndResultsMatchGridOrder) {
  const auto dir = testing::scratch("order");
  const Experiment x = synthetic("[sweep]\n\"x.cost\" = [1, 4, 2, 8, 3]\nnodes = [3, 7]\n", 3);
  auto run = [&](const fs::path& out, bool longest_first, RecordingModel& model) {
    RunnerOptions o;
    o.out_dir = out.string();
    o.jobs = 1;  // one worker: the start order is the hand-out order
    o.longest_first = longest_first;
    run_experiment(x, model, o);
    return ResultsDb(out.string(), ResultsDb::Mode::kRead).read_all();
  };
  RecordingModel sorted_model;
  RecordingModel grid_model;
  const std::vector<RunRecord> sorted = run(dir / "sorted", true, sorted_model);
  const std::vector<RunRecord> grid = run(dir / "grid", false, grid_model);

  const std::vector<double> started = sorted_model.started();
  ASSERT_EQ(started.size(), x.runs());
  EXPECT_TRUE(std::is_sorted(started.rbegin(), started.rend()));
  EXPECT_EQ(started.front(), 8.0);
  EXPECT_EQ(started.back(), 1.0);
  EXPECT_EQ(grid_model.started().front(), 1.0);  // grid order starts with point 0

  ASSERT_EQ(sorted.size(), grid.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    EXPECT_EQ(sorted[i].run, grid[i].run);
    EXPECT_EQ(sorted[i].seed, grid[i].seed);
    EXPECT_EQ(sorted[i].parameters, grid[i].parameters);
    EXPECT_EQ(sorted[i].status, grid[i].status);
    for (const auto& [name, value] : grid[i].metrics) {
      if (name == "run_time") continue;
      const double v = sorted[i].metrics.at(name);
      EXPECT_TRUE(v == value || (std::isnan(v) && std::isnan(value))) << name << " of run " << i;
    }
  }
}

TEST(RunOrder, ModelEstimatesGrowWithTheirSizeParameters) {
  const auto synthetic_model = make_synthetic_model();
  EXPECT_GT(synthetic_model->cost_estimate({{"sleep_ms", 10.0}}),
            synthetic_model->cost_estimate({{"sleep_ms", 1.0}}));
  EXPECT_GT(synthetic_model->cost_estimate({{"nodes", std::int64_t{1000}}}),
            synthetic_model->cost_estimate({{"nodes", std::int64_t{10}}}));

  const auto grow = make_grow_model("", "", ".");
  auto g = [&](std::int64_t years, const char* set) {
    return grow->cost_estimate({{"years", years}, {"set", std::string(set)}});
  };
  EXPECT_GT(g(30, "G"), g(20, "O"));  // age dominates
  EXPECT_GE(g(30, "T"), g(30, "O"));
  EXPECT_GT(g(30, "O"), g(30, "G"));

  const auto dir = testing::scratch("order_lsystem");
  const std::string file = testing::write(dir / "line.l", testing::kLineLSystem);
  const auto lsystem = make_lsystem_model(file, "", false);
  EXPECT_GT(lsystem->cost_estimate({{"steps", std::int64_t{8}}}),
            lsystem->cost_estimate({{"steps", std::int64_t{7}}}));
}

}  // namespace
}  // namespace fspm::experiments
