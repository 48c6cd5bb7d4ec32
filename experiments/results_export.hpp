#pragma once
// Exports and summaries of a result database (fspm results export | show | merge).
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "experiments/results_db.hpp"

namespace fspm::experiments {

// CSV, one row per run: run, seed, status, seconds, one column per swept parameter (named as in
// the experiment file), one per metric. Empty cells for missing values (failed runs' metrics).
void write_results_csv(const ExperimentInfo& info, const std::vector<RunRecord>& runs,
                       std::ostream& out);
// One JSON document: the experiment and every run with all its columns.
std::string results_json(const ExperimentInfo& info, const std::vector<RunRecord>& runs);
// A summary (counts by status, run time, per-metric mean/min/max over successful runs, the first
// errors) as a JSON document, and as text for people.
std::string results_summary_json(const ExperimentInfo& info, const std::vector<RunRecord>& runs);
std::string results_summary_text(const ExperimentInfo& info, const std::vector<RunRecord>& runs);

struct MergeSummary {
  std::size_t inputs = 0;
  std::size_t rows = 0;        // rows written to the merged database
  std::size_t duplicates = 0;  // rows of a run already taken from an earlier input
  std::size_t missing = 0;     // runs of the experiment without a row in any input
};

// Combines the databases of shards of one experiment into a new database in `out_dir` (which
// must not hold one). Kept files are copied along. Throws IoError when the inputs belong to
// different experiments.
MergeSummary merge_results(const std::string& out_dir, const std::vector<std::string>& inputs);

}  // namespace fspm::experiments
