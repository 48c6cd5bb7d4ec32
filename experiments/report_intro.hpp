#pragma once
// The opening paragraphs of a report (fspm report), for a reader who did not write the
// experiment file: what was run (model, scene in words, swept values, replicates, recorded
// metrics), what the values of a grow experiment's `set` mean, what each comparison pairs and
// what each t-test asks, then the experiment's own [report] about text (what the literature
// found). What the tests found follows in report_findings.hpp.
#include <string>
#include <string_view>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/grow_set.hpp"

namespace fspm::experiments {

// Markdown paragraphs, each ending in a blank line.
std::string report_introduction(const Experiment& experiment);

}  // namespace fspm::experiments
