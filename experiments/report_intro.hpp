#pragma once
// The opening paragraphs of a report (fspm report), for a reader who did not write the
// experiment file: what was run (model, scene, swept values, replicates, recorded metrics), what
// the values of a grow experiment's `set` mean, what each comparison pairs and what each t-test
// asks, then the experiment's own [report] about text (what the literature found). After the
// tests, ttest_overview sums up how often each test came out significant.
#include <string>
#include <string_view>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/grow_set.hpp"

namespace fspm::experiments {

// Markdown paragraphs, each ending in a blank line.
std::string report_introduction(const Experiment& experiment);

// One bullet per [[ttest]]: in how many groups the test was significant at its alpha, which
// comparison had the larger mean there, and in how many it was not.
std::string ttest_overview(const Experiment& experiment, const std::vector<TTestRow>& tests);

}  // namespace fspm::experiments
