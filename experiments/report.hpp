#pragma once
// The Markdown report of a result database (fspm report): the run counts, one table of mean and
// standard deviation of every metric per parameter point (over its successful replicates), one
// table of marginal means per swept parameter, and the failed runs.
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/results_db.hpp"

namespace fspm::experiments {

std::string markdown_report(const ExperimentInfo& info, const std::vector<RunRecord>& runs);

// The experiment's [[table]]s: mean ± standard deviation of the listed metrics over the
// successful runs matching `where`, one row per combination of the `by` values (Pirk Table 4.2
// is such a table: nodes, growth and adaptation time per age).
std::string summary_tables_markdown(const Experiment& experiment,
                                    const std::vector<RunRecord>& runs);

}  // namespace fspm::experiments
