#include "experiments/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <ctime>
#include <deque>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "experiments/metrics.hpp"
#include "experiments/progress.hpp"
#include "experiments/results_db.hpp"
#include "experiments/run_execution.hpp"
#include "experiments/run_order.hpp"
#include "experiments/run_plan.hpp"
#include "fspm/memory_account.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/tree_file.hpp"
#include "fspm/warning.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Finished runs handed from the workers to the writer. Bounded: when runs finish faster than
// the database takes them (a quick model), workers wait instead of queueing without limit, so
// memory stays flat and an interrupt leaves at most kMaxQueued records to write.
class Mailbox {
 public:
  static constexpr std::size_t kMaxQueued = 1024;

  void put(RunRecord r) {
    {
      std::unique_lock lock(mutex_);
      space_.wait(lock, [&] { return queue_.size() < kMaxQueued || closed_; });
      if (closed_) return;  // the writer is gone (an error): nobody would take it
      queue_.push_back(std::move(r));
    }
    ready_.notify_one();
  }
  // Releases waiting workers and drops later records; for leaving the writer loop on an error.
  void close() {
    {
      std::lock_guard lock(mutex_);
      closed_ = true;
    }
    space_.notify_all();
  }
  void worker_done() {
    {
      std::lock_guard lock(mutex_);
      ++finished_workers_;
    }
    ready_.notify_one();
  }
  // Waits up to `wait` for records; returns false once every worker is done and all is taken.
  bool take(std::vector<RunRecord>& out, std::size_t workers, std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, wait, [&] { return !queue_.empty() || finished_workers_ == workers; });
    while (!queue_.empty()) {
      out.push_back(std::move(queue_.front()));
      queue_.pop_front();
    }
    space_.notify_all();
    return !(finished_workers_ == workers && out.empty());
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::condition_variable space_;
  std::deque<RunRecord> queue_;
  std::size_t finished_workers_ = 0;
  bool closed_ = false;
};

// Stops the workers and opens the mailbox when the writer loop is left by an exception, so
// that joining the workers cannot wait for a writer that is gone.
class StopOnExit {
 public:
  StopOnExit(Mailbox& mailbox, std::atomic<bool>& stop) : mailbox_(mailbox), stop_(stop) {}
  ~StopOnExit() {
    stop_ = true;
    mailbox_.close();
  }
  StopOnExit(const StopOnExit&) = delete;
  StopOnExit& operator=(const StopOnExit&) = delete;

 private:
  Mailbox& mailbox_;
  std::atomic<bool>& stop_;
};

// Starts up to `workers` threads running `work`. When the system refuses a thread (an
// address-space limit, a cap on processes), the jobs already started carry on alone, with a
// warning: a worker left waiting for a writer that never comes would hang the process, even
// against SIGTERM. Throws IoError when not even one thread starts.
template <class Work>
std::vector<std::jthread> start_workers(std::size_t workers, Work& work, Mailbox& mailbox,
                                        std::atomic<bool>& stop_all) {
  std::vector<std::jthread> pool;
  pool.reserve(workers);
  try {
    for (std::size_t w = 0; w < workers; ++w) pool.emplace_back(work);
  } catch (const std::system_error& e) {
    if (pool.empty()) {
      throw IoError(std::string("--jobs: cannot start a job thread: ") + e.what());
    }
    warn("--jobs: the system started only " + std::to_string(pool.size()) + " of " +
         std::to_string(workers) + " job threads (" + e.what() + "): running with " +
         std::to_string(pool.size()) + "; give a lower --jobs");
  } catch (...) {
    // Anything else: stop the started workers before they are joined.
    stop_all = true;
    mailbox.close();
    throw;
  }
  return pool;
}

}  // namespace

ExperimentInfo experiment_info(const Experiment& experiment) {
  ExperimentInfo info;
  info.name = experiment.name;
  // Absolute, so that `fspm report` and `fspm compare` find the model's files (resolved next
  // to the experiment file) from any working folder.
  info.experiment_path =
      experiment.path.empty()
          ? experiment.path
          : std::filesystem::absolute(experiment.path).lexically_normal().string();
  info.experiment_text = experiment.text;
  info.total_runs = experiment.runs();
  info.swept = experiment.swept_names();
  info.metrics = experiment.metrics;
  return info;
}

void count_recorded(const std::vector<RunRecord>& batch, RunnerSummary& summary) {
  for (const RunRecord& r : batch) {
    ++summary.ran;
    if (r.status == RunStatus::kOk) ++summary.ok;
    if (r.status == RunStatus::kError) ++summary.failed;
    if (r.status == RunStatus::kTimeout) ++summary.timed_out;
  }
}

void check_run_list_memory(const Experiment& experiment, std::size_t runs,
                           const RunnerOptions& options) {
  const double shard_runs =
      std::ceil(static_cast<double>(runs) /
                static_cast<double>(std::max<std::size_t>(options.shard_count, 1)));
  const double per_run =
      sizeof(std::size_t) + (options.longest_first ? 3 * sizeof(std::size_t) + sizeof(double) : 0);
  check_memory(static_cast<double>(runs) + shard_runs * per_run,
               "the list of " + std::to_string(runs) + " runs", experiment.path);
}

void RunnerOptions::validate() const {
  if (shard_count == 0 || shard_index >= shard_count) {
    throw ValueError("runner: shard_index/shard_count " + std::to_string(shard_index) + "/" +
                     std::to_string(shard_count) +
                     " does not exist (expected I/N with 0 <= I < N, --shard)");
  }
}

RunnerSummary run_experiment(const Experiment& experiment, const Model& model,
                             const RunnerOptions& options) {
  const Clock::time_point start = Clock::now();
  options.validate();
  check_run_file_writers(experiment, options.file_writers);
  const RunPlan plan(experiment);
  check_run_list_memory(experiment, plan.size(), options);
  const ExperimentInfo info = experiment_info(experiment);
  ResultsDb db(options.out_dir,
               options.resume ? ResultsDb::Mode::kResume : ResultsDb::Mode::kCreate, info);

  RunnerSummary summary;
  summary.database = db.path();
  summary.total_runs = plan.size();
  const std::vector<char> done = db.recorded_runs();
  std::vector<std::size_t> pending;
  for (std::size_t i = options.shard_index; i < plan.size(); i += options.shard_count) {
    ++summary.shard_runs;
    if (done[i] != 0) {
      ++summary.already_done;
    } else {
      pending.push_back(i);
    }
  }
  if (options.longest_first) {
    pending = longest_first(plan, model, std::move(pending), options.interrupt);
  }
  const ExecutionSettings settings = execution_settings(
      experiment, options.out_dir, options.time_limit_s, options.interrupt, options.file_writers);
  const std::size_t hardware = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t workers =
      std::max<std::size_t>(1, std::min(options.jobs == 0 ? hardware : options.jobs,
                                        std::max<std::size_t>(pending.size(), 1)));
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop_all{false};  // a write failure stops the workers too
  Mailbox mailbox;

  auto interrupted = [&] {
    return stop_all.load() || (options.interrupt != nullptr && options.interrupt->load());
  };

  auto work = [&] {
    // Combined flag seen by RunContext: the user's interrupt or a writer failure.
    for (;;) {
      if (interrupted()) break;
      const std::size_t k = next.fetch_add(1);
      if (k >= pending.size()) break;
      std::optional<RunRecord> record;
      {
        // The workers share the one memory limit: each run reserves what it checks.
        const MemoryAccount account;
        record = execute_run(model, plan.run(pending[k]), settings);
      }
      if (!record) continue;
      mailbox.put(std::move(*record));
    }
    mailbox.worker_done();
  };

  std::vector<std::jthread> pool = start_workers(workers, work, mailbox, stop_all);
  const std::size_t started = pool.size();
  const StopOnExit stop_on_exit(mailbox, stop_all);

  // This thread is the only writer: it commits whatever finished, in one transaction per batch,
  // so the database is never the bottleneck and a kill loses at most the uncommitted batch.
  ProgressReporter progress(options.progress, pending.size(), options.progress_bar,
                            options.progress_interval_s);
  std::vector<RunRecord> batch;
  std::exception_ptr write_error;
  while (mailbox.take(batch, started, std::chrono::milliseconds(100))) {
    if (batch.empty() || write_error) {
      batch.clear();
      continue;
    }
    try {
      db.insert(batch);
    } catch (...) {
      write_error = std::current_exception();
      stop_all = true;
      batch.clear();
      continue;
    }
    count_recorded(batch, summary);
    batch.clear();
    progress.update(summary.ran, summary.failed + summary.timed_out);
  }
  pool.clear();
  if (write_error) std::rethrow_exception(write_error);
  summary.interrupted = summary.ran < pending.size();
  progress.update(summary.ran, summary.failed + summary.timed_out, true);
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace fspm::experiments
