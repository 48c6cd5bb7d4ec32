#include "experiments/runner.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "experiments/model_factory.hpp"
#include "experiments/results_db.hpp"
#include "experiments/results_export.hpp"
#include "experiments/run_plan.hpp"
#include "fspm/error.hpp"
#include "test_files.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;

Experiment synthetic(const std::string& body, int replicates = 1) {
  return parse_experiment(
      "[experiment]\nname = \"s\"\nseed = 11\nreplicates = " + std::to_string(replicates) +
          "\n[model]\nkind = \"synthetic\"\n" + body,
      "s.toml");
}

RunnerSummary run(const Experiment& x, const fs::path& out, std::size_t jobs = 2,
                  bool resume = false) {
  const auto model = make_model(x);
  RunnerOptions o;
  o.out_dir = out.string();
  o.jobs = jobs;
  o.resume = resume;
  return run_experiment(x, *model, o);
}

TEST(Runner, EveryRunIsOneRowWithItsSeedAndMetrics) {
  const auto dir = testing::scratch("rows");
  const Experiment x = synthetic("[sweep]\nnodes = { range = [1, 11] }\n", 3);
  const RunnerSummary s = run(x, dir / "out");
  EXPECT_EQ(s.ran, 30u);
  EXPECT_EQ(s.ok, 30u);
  EXPECT_FALSE(s.interrupted);
  const ResultsDb db((dir / "out").string(), ResultsDb::Mode::kRead);
  const auto rows = db.read_all();
  ASSERT_EQ(rows.size(), 30u);
  const RunPlan plan(x);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].run, i);
    EXPECT_EQ(rows[i].seed, plan.run(i).seed);
    EXPECT_EQ(rows[i].parameters, plan.run(i).parameters);
    // A chain of `nodes` unit internodes is `nodes` high.
    EXPECT_EQ(rows[i].metrics.at("height"), static_cast<double>(i / 3 + 1));
    EXPECT_GE(rows[i].metrics.at("run_time"), 0.0);
  }
}

TEST(Runner, AFailingRunIsRecordedAndTheSweepGoesOn) {
  const auto dir = testing::scratch("fail");
  const Experiment x = synthetic("[sweep]\nfail = [0, 1, 0]\n");
  const RunnerSummary s = run(x, dir / "out");
  EXPECT_EQ(s.ok, 2u);
  EXPECT_EQ(s.failed, 1u);
  const auto rows = ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[1].status, RunStatus::kError);
  EXPECT_NE(rows[1].error.find("synthetic failure"), std::string::npos);
  EXPECT_TRUE(std::isnan(rows[1].metrics.at("height")));
  EXPECT_EQ(rows[2].status, RunStatus::kOk);
}

TEST(Runner, ARunOverItsTimeLimitIsStoppedAndRecorded) {
  const auto dir = testing::scratch("timeout");
  const Experiment x = synthetic("[runner]\ntime_limit_s = 0.2\n[sweep]\nsleep_ms = [0, 60000]\n");
  const auto t0 = std::chrono::steady_clock::now();
  const RunnerSummary s = run(x, dir / "out");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0);
  EXPECT_EQ(s.timed_out, 1u);
  const auto rows = ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].status, RunStatus::kOk);
  EXPECT_EQ(rows[1].status, RunStatus::kTimeout);
  EXPECT_GE(rows[1].seconds, 0.2);
  EXPECT_LT(rows[1].seconds, 5.0);
}

// A sweep killed with SIGKILL at random moments, resumed each time: in the end every run has
// exactly one row, with the parameters and seed the plan gives it.
TEST(Runner, KillNineAtRandomPointsThenResumeLosesAndDuplicatesNothing) {
  const auto dir = testing::scratch("kill");
  const fs::path out = dir / "out";
  const Experiment x =
      synthetic("[parameters]\nsleep_ms = 5\n[sweep]\n\"x.i\" = { range = [0, 150] }\n", 2);
  std::mt19937_64 rng(2024);
  std::size_t kills = 0;
  // 300 runs of 5 ms on 2 threads need at least 750 ms; the attempts last at most 500 ms.
  for (int attempt = 0; attempt < 5; ++attempt) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      try {
        run(x, out, 2, true);
      } catch (...) {
        ::_exit(3);
      }
      ::_exit(0);
    }
    const int delay_ms = std::uniform_int_distribution<int>(5, 100)(rng);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    if (::kill(child, SIGKILL) == 0) ++kills;
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 3) << "the child failed to run";
  }
  EXPECT_GT(kills, 0u);
  // Killed before its database was complete, a run leaves none (it is renamed into place), so
  // a database that exists always opens for reading.
  std::size_t before = 0;
  if (fs::exists(out / kDatabaseFile)) {
    const ResultsDb db(out.string(), ResultsDb::Mode::kRead);
    before = db.row_count();
  }
  EXPECT_LT(before, 300u) << "the kills came too late to test anything";
  const RunnerSummary s = run(x, out, 2, true);
  EXPECT_EQ(s.already_done, before);
  EXPECT_EQ(s.ran, 300u - before);
  const auto rows = ResultsDb(out.string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(rows.size(), 300u);
  const RunPlan plan(x);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].run, i);
    EXPECT_EQ(rows[i].seed, plan.run(i).seed);
    EXPECT_EQ(rows[i].parameters, plan.run(i).parameters);
    EXPECT_EQ(rows[i].status, RunStatus::kOk);
  }
}

TEST(Runner, InterruptLeavesUnfinishedRunsForResume) {
  const auto dir = testing::scratch("interrupt");
  const Experiment x =
      synthetic("[parameters]\nsleep_ms = 20\n[sweep]\n\"x.i\" = { range = [0, 40] }\n");
  const auto model = make_model(x);
  std::atomic<bool> stop{false};
  RunnerOptions o;
  o.out_dir = (dir / "out").string();
  o.jobs = 2;
  o.interrupt = &stop;
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    stop = true;
  });
  const RunnerSummary s = run_experiment(x, *model, o);
  stopper.join();
  EXPECT_TRUE(s.interrupted);
  EXPECT_LT(s.ran, 40u);
  const RunnerSummary r = run(x, dir / "out", 2, true);
  EXPECT_EQ(r.already_done + r.ran, 40u);
  EXPECT_EQ(ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).row_count(), 40u);
}

TEST(Runner, ShardsMergeIntoTheWholeExperiment) {
  const auto dir = testing::scratch("shards");
  const Experiment x = synthetic("[sweep]\nnodes = { range = [1, 8] }\n", 2);
  const auto model = make_model(x);
  for (std::size_t i = 0; i < 3; ++i) {
    RunnerOptions o;
    o.out_dir = (dir / ("shard-" + std::to_string(i))).string();
    o.shard_index = i;
    o.shard_count = 3;
    const RunnerSummary s = run_experiment(x, *model, o);
    EXPECT_EQ(s.shard_runs, i == 0 ? 5u : (i == 1 ? 5u : 4u));
  }
  const MergeSummary m = merge_results((dir / "merged").string(),
                                       {(dir / "shard-0").string(), (dir / "shard-1").string(),
                                        (dir / "shard-2").string(), (dir / "shard-1").string()});
  EXPECT_EQ(m.rows, 14u);
  EXPECT_EQ(m.duplicates, 5u);
  EXPECT_EQ(m.missing, 0u);
  run(x, dir / "whole", 1);
  const auto merged = ResultsDb((dir / "merged").string(), ResultsDb::Mode::kRead).read_all();
  const auto whole = ResultsDb((dir / "whole").string(), ResultsDb::Mode::kRead).read_all();
  ASSERT_EQ(merged.size(), whole.size());
  for (std::size_t i = 0; i < whole.size(); ++i) {
    EXPECT_EQ(merged[i].seed, whole[i].seed);
    EXPECT_EQ(merged[i].metrics.at("nodes"), whole[i].metrics.at("nodes"));
  }
}

TEST(ResultsDb, LeftoverOfAKilledCreationIsReplaced) {
  const auto dir = testing::scratch("partial");
  fs::create_directories(dir / "out");
  std::ofstream(dir / "out" / "results.sqlite.partial") << "half a database";
  const Experiment x = synthetic("");
  run(x, dir / "out");
  EXPECT_FALSE(fs::exists(dir / "out" / "results.sqlite.partial"));
  EXPECT_EQ(ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).row_count(), 1u);
}

TEST(ResultsDb, ExistingDatabaseIsNeverOverwritten) {
  const auto dir = testing::scratch("exists");
  const Experiment x = synthetic("");
  run(x, dir / "out");
  EXPECT_THROW(run(x, dir / "out"), IoError);
  // Another experiment cannot resume it.
  const Experiment other = synthetic("[parameters]\nnodes = 4\n");
  EXPECT_THROW(run(other, dir / "out", 1, true), IoError);
  EXPECT_EQ(ResultsDb((dir / "out").string(), ResultsDb::Mode::kRead).row_count(), 1u);
}

TEST(ResultsDb, CorruptedDatabaseIsReportedAndLeftUntouched) {
  const auto dir = testing::scratch("corrupt");
  fs::create_directories(dir / "out");
  const std::string garbage(8192, 'x');
  testing::write(dir / "out" / kDatabaseFile, "SQLite format 3" + garbage);
  try {
    run(synthetic(""), dir / "out", 1, true);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt"), std::string::npos) << e.what();
  }
  std::ifstream in(dir / "out" / kDatabaseFile, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  EXPECT_EQ(bytes.str(), "SQLite format 3" + garbage);
}

TEST(ResultsDb, ADirectoryBeingWrittenIsLocked) {
  const auto dir = testing::scratch("locked");
  const Experiment x = synthetic("");
  ExperimentInfo info;
  info.experiment_text = x.text;
  info.total_runs = 1;
  const ResultsDb writer((dir / "out").string(), ResultsDb::Mode::kResume, info);
  try {
    run(x, dir / "out", 1, true);
    FAIL();
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("locked"), std::string::npos) << e.what();
  }
}

TEST(ResultsExport, CsvHasTheDocumentedColumns) {
  const auto dir = testing::scratch("csv");
  const Experiment x = parse_experiment(
      "[experiment]\nname = \"c\"\n[model]\nkind = \"synthetic\"\n[parameters]\nlength = 0.5\n"
      "[sweep]\nnodes = [2, 4]\n\"x.tag\" = [\"a,b\"]\n[outputs]\nmetrics = [\"height\", "
      "\"internodes\"]\n",
      "c.toml");
  run(x, dir / "out");
  const ResultsDb db((dir / "out").string(), ResultsDb::Mode::kRead);
  std::ostringstream csv;
  write_results_csv(db.info(), db.read_all(), csv);
  std::istringstream lines(csv.str());
  std::string header, first, second;
  std::getline(lines, header);
  std::getline(lines, first);
  std::getline(lines, second);
  EXPECT_EQ(header, "run,seed,status,seconds,nodes,x.tag,height,internodes");
  EXPECT_EQ(first.substr(0, 2), "0,");
  // nodes 2 of length 0.5: height 1; the text cell with a comma is quoted.
  EXPECT_NE(first.find(",ok,"), std::string::npos);
  EXPECT_EQ(first.substr(first.find(",2,\"a,b\",")), ",2,\"a,b\",1,2");
  EXPECT_EQ(second.substr(second.find(",4,\"a,b\",")), ",4,\"a,b\",2,4");
}

}  // namespace
}  // namespace fspm::experiments
