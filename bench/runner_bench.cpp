// Experiment runner: overhead per run with a model that does nothing (goal < 1 ms),
// results per second the SQLite writer sustains, and parallel efficiency of busy runs on 1 vs 2
// threads.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "experiments/results_db.hpp"
#include "experiments/runner.hpp"

namespace {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;

class TrivialModel final : public ex::Model {
 public:
  explicit TrivialModel(double busy_ms = 0.0) : busy_ms_(busy_ms) {}
  void check_parameter(const std::string&, const ex::ParameterValue&) const override {}
  ex::RunResult run(const ex::ParameterSet&, std::uint64_t seed,
                    const ex::RunContext&) const override {
    // Busy work (not sleep) so that parallel efficiency measures real CPU sharing.
    const auto until = std::chrono::steady_clock::now() +
                       std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double, std::milli>(busy_ms_));
    std::uint64_t x = seed;
    while (busy_ms_ > 0.0 && std::chrono::steady_clock::now() < until) {
      for (int i = 0; i < 1000; ++i) x = x * 6364136223846793005ULL + 1;
    }
    benchmark::DoNotOptimize(x);
    ex::RunResult r;
    r.metrics = {{"height", 1.0}, {"internodes", 2.0}};
    return r;
  }

 private:
  double busy_ms_;
};

ex::Experiment experiment(std::size_t runs) {
  return ex::parse_experiment(
      "[experiment]\nname = \"bench\"\n[model]\nkind = \"synthetic\"\n"
      "[sweep]\n\"x.i\" = { range = [0, " +
          std::to_string(runs) + "] }\n[outputs]\nmetrics = [\"height\", \"internodes\"]\n",
      "bench.toml");
}

fs::path fresh_dir() {
  static int counter = 0;
  const fs::path dir =
      fs::temp_directory_path() /
      ("fspm_runner_bench_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::remove_all(dir);
  return dir;
}

// Whole runner (plan, thread pool, SQLite rows) per run with a model that returns at once.
void BM_RunnerOverheadPerRun(benchmark::State& state) {
  const auto runs = static_cast<std::size_t>(state.range(0));
  const ex::Experiment x = experiment(runs);
  const TrivialModel model;
  for (auto _ : state) {
    state.PauseTiming();
    const fs::path dir = fresh_dir();
    state.ResumeTiming();
    ex::RunnerOptions o;
    o.out_dir = dir.string();
    o.jobs = static_cast<std::size_t>(state.range(1));
    const ex::RunnerSummary s = ex::run_experiment(x, model, o);
    benchmark::DoNotOptimize(s.ran);
    state.PauseTiming();
    fs::remove_all(dir);
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(runs));
}
BENCHMARK(BM_RunnerOverheadPerRun)
    ->Args({2000, 1})
    ->Args({2000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Rows per second the database takes in batches of `batch` (one transaction per batch).
void BM_DatabaseInsert(benchmark::State& state) {
  const auto batch = static_cast<std::size_t>(state.range(0));
  const fs::path dir = fresh_dir();
  ex::ExperimentInfo info;
  info.name = "bench";
  info.total_runs = 1u << 30;
  info.swept = {"x.i"};
  info.metrics = {"height", "internodes", "total_length", "crown_width"};
  ex::ResultsDb db(dir.string(), ex::ResultsDb::Mode::kCreate, info);
  std::size_t next = 0;
  std::vector<ex::RunRecord> records(batch);
  for (auto _ : state) {
    for (ex::RunRecord& r : records) {
      r.run = next++;
      r.seed = r.run * 7919;
      r.seconds = 0.001;
      r.parameters = {{"x.i", static_cast<std::int64_t>(r.run)}, {"steps", std::int64_t{6}}};
      r.metrics = {
          {"height", 1.5}, {"internodes", 120}, {"total_length", 33.25}, {"crown_width", 2.0}};
      r.finished_at = "2026-01-01T00:00:00Z";
    }
    db.insert(records);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(batch));
  fs::remove_all(dir);
}
BENCHMARK(BM_DatabaseInsert)
    ->Arg(1)
    ->Arg(100)
    ->Arg(1000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// 200 runs of 5 ms busy work on `jobs` threads; efficiency = t(1) / (jobs * t(jobs)).
void BM_ParallelRuns(benchmark::State& state) {
  const ex::Experiment x = experiment(200);
  const TrivialModel model(5.0);
  for (auto _ : state) {
    state.PauseTiming();
    const fs::path dir = fresh_dir();
    state.ResumeTiming();
    ex::RunnerOptions o;
    o.out_dir = dir.string();
    o.jobs = static_cast<std::size_t>(state.range(0));
    benchmark::DoNotOptimize(ex::run_experiment(x, model, o).ran);
    state.PauseTiming();
    fs::remove_all(dir);
    state.ResumeTiming();
  }
  state.SetItemsProcessed(state.iterations() * 200);
}
BENCHMARK(BM_ParallelRuns)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
