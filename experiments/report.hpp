#pragma once
// The Markdown report of a result database (fspm report): the run counts, one table of mean and
// standard deviation of every metric per parameter point (over its successful replicates), one
// table of marginal means per swept parameter, and the failed runs.
#include <string>
#include <vector>

#include "experiments/results_db.hpp"

namespace fspm::experiments {

std::string markdown_report(const ExperimentInfo& info, const std::vector<RunRecord>& runs);

}  // namespace fspm::experiments
