#include "experiments/mpi_runner.hpp"

#include "fspm/error.hpp"

#ifdef FSPM_HAVE_MPI
#include <mpi.h>

#include <chrono>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "experiments/progress.hpp"
#include "experiments/run_execution.hpp"
#include "experiments/run_order.hpp"
#include "experiments/run_plan.hpp"
#endif

namespace fspm::experiments {

#ifndef FSPM_HAVE_MPI

bool mpi_available() { return false; }

RunnerSummary run_experiment_mpi(const Experiment&, const Model&, const RunnerOptions&, bool&) {
  throw ValueError("--mpi: this fspm was built without MPI (install libopenmpi-dev and rebuild)");
}

#else

namespace {

using Clock = std::chrono::steady_clock;
constexpr int kTagReady = 1;      // worker -> root: give me a run
constexpr int kTagResult = 2;     // worker -> root: a finished run (and give me the next)
constexpr int kTagWork = 3;       // root -> worker: a run index, or -1: stop
constexpr int kTagAbandoned = 4;  // worker -> root: interrupted run without a row

void send_index(int rank, long long index) {
  MPI_Send(&index, 1, MPI_LONG_LONG, rank, kTagWork, MPI_COMM_WORLD);
}

RunnerSummary worker(const Experiment& experiment, const Model& model,
                     const RunnerOptions& options) {
  const RunPlan plan(experiment);
  const ExecutionSettings settings = execution_settings(
      experiment, options.out_dir, options.time_limit_s, options.interrupt, options.file_writers);
  RunnerSummary summary;
  MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagReady, MPI_COMM_WORLD);
  for (;;) {
    long long index = -1;
    MPI_Recv(&index, 1, MPI_LONG_LONG, 0, kTagWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (index < 0) break;
    const std::optional<RunRecord> record =
        execute_run(model, plan.run(static_cast<std::size_t>(index)), settings);
    if (!record) {
      MPI_Send(nullptr, 0, MPI_CHAR, 0, kTagAbandoned, MPI_COMM_WORLD);
      continue;
    }
    ++summary.ran;
    const std::string text = record_to_json(*record);
    MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
  }
  return summary;
}

RunnerSummary root(const Experiment& experiment, const Model& model, const RunnerOptions& options,
                   int ranks) {
  const Clock::time_point start = Clock::now();
  RunnerSummary summary;
  std::vector<std::size_t> pending;
  std::unique_ptr<ResultsDb> db;
  try {
    options.validate();
    check_run_file_writers(experiment, options.file_writers);
    check_run_list_memory(experiment, experiment.runs(), options);
    db = std::make_unique<ResultsDb>(
        options.out_dir, options.resume ? ResultsDb::Mode::kResume : ResultsDb::Mode::kCreate,
        experiment_info(experiment));
    const std::vector<char> done = db->recorded_runs();
    for (std::size_t i = options.shard_index; i < done.size(); i += options.shard_count) {
      ++summary.shard_runs;
      if (done[i] != 0) {
        ++summary.already_done;
      } else {
        pending.push_back(i);
      }
    }
  } catch (...) {
    for (int r = 1; r < ranks; ++r) send_index(r, -1);  // nobody waits for work that never comes
    throw;
  }
  summary.database = db->path();
  summary.total_runs = experiment.runs();
  const RunPlan plan(experiment);
  if (options.longest_first) {
    pending = longest_first(plan, model, std::move(pending), options.interrupt);
  }
  const ExecutionSettings settings = execution_settings(
      experiment, options.out_dir, options.time_limit_s, options.interrupt, options.file_writers);

  std::mutex mutex;  // guards next and local_done
  std::size_t next = 0;
  std::deque<RunRecord> local_done;
  bool local_finished = false;
  auto interrupted = [&] { return options.interrupt != nullptr && options.interrupt->load(); };
  auto take = [&]() -> long long {
    std::lock_guard lock(mutex);
    if (interrupted() || next >= pending.size()) return -1;
    return static_cast<long long>(pending[next++]);
  };
  // Rank 0 computes too, on one thread: only this (main) thread calls MPI (MPI_THREAD_FUNNELED).
  std::jthread local([&] {
    for (long long index; (index = take()) >= 0;) {
      std::optional<RunRecord> r =
          execute_run(model, plan.run(static_cast<std::size_t>(index)), settings);
      std::lock_guard lock(mutex);
      if (r) local_done.push_back(std::move(*r));
    }
    std::lock_guard lock(mutex);
    local_finished = true;
  });

  ProgressReporter progress(options.progress, pending.size(), options.progress_bar,
                            options.progress_interval_s);
  std::vector<RunRecord> batch;
  Clock::time_point last_flush = Clock::now();
  auto flush = [&] {
    db->insert(batch);
    count_recorded(batch, summary);
    batch.clear();
    last_flush = Clock::now();
    progress.update(summary.ran, summary.failed + summary.timed_out);
  };
  int active = ranks - 1;
  for (;;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag != 0) {
      int count = 0;
      MPI_Get_count(&status, MPI_CHAR, &count);
      std::string text(static_cast<std::size_t>(count), '\0');
      MPI_Recv(text.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      if (status.MPI_TAG == kTagResult) batch.push_back(record_from_json(text));
      const long long index = take();
      send_index(status.MPI_SOURCE, index);
      if (index < 0) --active;
    } else {
      bool local_over = false;
      {
        std::lock_guard lock(mutex);
        while (!local_done.empty()) {
          batch.push_back(std::move(local_done.front()));
          local_done.pop_front();
        }
        local_over = local_finished;
      }
      if (!batch.empty() &&
          (batch.size() >= 256 || Clock::now() - last_flush > std::chrono::milliseconds(100))) {
        flush();
      }
      if (active == 0 && local_over) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  local.join();
  {
    std::lock_guard lock(mutex);
    while (!local_done.empty()) {
      batch.push_back(std::move(local_done.front()));
      local_done.pop_front();
    }
  }
  flush();
  summary.interrupted = summary.ran < pending.size();
  progress.update(summary.ran, summary.failed + summary.timed_out, true);
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace

bool mpi_available() { return true; }

RunnerSummary run_experiment_mpi(const Experiment& experiment, const Model& model,
                                 const RunnerOptions& options, bool& is_root) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized == 0) {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  }
  struct Finalizer {
    bool owned;
    ~Finalizer() {
      if (owned) MPI_Finalize();
    }
  } finalizer{initialized == 0};
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  is_root = rank == 0;
  if (rank == 0) return root(experiment, model, options, ranks);
  return worker(experiment, model, options);
}

#endif

}  // namespace fspm::experiments
