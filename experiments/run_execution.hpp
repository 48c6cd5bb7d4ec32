#pragma once
// One run from its spec to its database row: the model is run under the time limit, failures are
// caught and recorded, the requested metrics picked, kept files written. Shared by the thread
// runner and the MPI ranks.
#include <atomic>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/model.hpp"
#include "experiments/run_files.hpp"
#include "experiments/run_plan.hpp"
#include "experiments/run_record.hpp"

namespace fspm::experiments {

struct ExecutionSettings {
  const Experiment* experiment = nullptr;
  std::optional<double> time_limit_s;
  std::string out_dir;  // kept files go to out_dir/runs/
  bool keep_tree = false;
  // The other kept kinds, in outputs.keep order, with their writers.
  std::vector<std::pair<KeptFile, RunFileWriter>> file_writers;
  const std::atomic<bool>* interrupt = nullptr;
  // outputs.reference, read once, when distance_to_reference is recorded.
  std::shared_ptr<const TreeGraph> reference;
};

// Throws ValueError (check_run_file_writers) when a kept kind has no writer in `writers`.
ExecutionSettings execution_settings(const Experiment& experiment, const std::string& out_dir,
                                     std::optional<double> time_limit_override,
                                     const std::atomic<bool>* interrupt,
                                     const RunFileWriters& writers = {});

// nullopt when the run was abandoned because of an interrupt: it gets no row.
std::optional<RunRecord> execute_run(const Model& model, const RunSpec& spec,
                                     const ExecutionSettings& settings);

// The record as one JSON text and back (rows sent between MPI ranks).
std::string record_to_json(const RunRecord& record);
RunRecord record_from_json(const std::string& text);

}  // namespace fspm::experiments
