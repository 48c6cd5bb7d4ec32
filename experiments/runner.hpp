#pragma once
// The local runner: the runs of an experiment (or of one shard of it) on a pool of threads, each
// finished run written as one row of the result database by a single writer thread, in batches.
// Runs already in the database are skipped on resume, so a sweep killed at any point (even with
// kill -9) continues with exactly the runs that have no row.
#include <atomic>
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/model.hpp"
#include "experiments/results_db.hpp"
#include "experiments/run_files.hpp"

namespace fspm::experiments {

struct RunnerOptions {
  std::string out_dir;
  std::size_t jobs = 0;         // worker threads; 0: one per hardware thread
  bool resume = false;          // continue the database in out_dir (or start one)
  std::size_t shard_index = 0;  // this process runs the runs with index % shard_count == index
  std::size_t shard_count = 1;
  std::optional<double> time_limit_s;  // overrides the experiment's [runner] time_limit_s
  // Set (e.g. from a SIGINT handler) to stop: no new run starts, running ones are abandoned at
  // their next check and not recorded, finished ones are committed.
  const std::atomic<bool>* interrupt = nullptr;
  std::ostream* progress = nullptr;  // progress lines (stderr); null: silent
  bool progress_bar = false;         // a redrawn bar with ETA (terminal) instead of plain lines
  double progress_interval_s = 5.0;  // plain lines at most this often
  // Hand out the runs costliest first (Model::cost_estimate, experiments/run_order.hpp) instead
  // of in index order. Results are the same either way.
  bool longest_first = true;
  // Writers of the kept kinds other than "tree" (run_files.hpp); a kept kind without one is an
  // error before any run.
  RunFileWriters file_writers;

  // Throws ValueError naming the field: a shard that does not exist (shard_index >= shard_count).
  void validate() const;
};

struct RunnerSummary {
  std::string database;
  std::size_t total_runs = 0;    // of the whole experiment
  std::size_t shard_runs = 0;    // of this shard
  std::size_t already_done = 0;  // rows found on resume
  std::size_t ran = 0;           // recorded by this call
  std::size_t ok = 0;
  std::size_t failed = 0;
  std::size_t timed_out = 0;
  bool interrupted = false;
  double seconds = 0.0;  // wall clock of this call
};

// What the result database records about `experiment`.
ExperimentInfo experiment_info(const Experiment& experiment);

// Checks that the run list of one shard fits the memory budget before anything is allocated or
// the database exists: per run a done flag; per run of the shard its index, and for the
// longest-first order a cost, a position, stable_sort's buffer and the sorted index
// (run_order.cpp). Throws MemoryLimitError naming the experiment file. Shared by the thread and
// MPI runners.
void check_run_list_memory(const Experiment& experiment, std::size_t runs,
                           const RunnerOptions& options);

// Throws IoError for database problems (locked, corrupted, another experiment's) before any run.
// Counts a batch of recorded runs into the summary (ran, ok, failed, timed out); shared by the
// thread and MPI runners.
void count_recorded(const std::vector<RunRecord>& batch, RunnerSummary& summary);

RunnerSummary run_experiment(const Experiment& experiment, const Model& model,
                             const RunnerOptions& options);

}  // namespace fspm::experiments
