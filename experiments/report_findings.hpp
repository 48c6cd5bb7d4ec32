#pragma once
// The opening "Findings" of a report, written from the t-tests: per group, whether each tested
// comparison is like the other (no difference after Holm's correction over all tests, Holm 1979)
// or unlike it (larger or smaller), with the effect size (mean difference and its 95 %
// confidence interval, Cohen's d) beside p and the Holm-corrected p, and a plain warning when a
// group holds fewer than kFewPairs pairs.
#include <cstddef>
#include <string>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"

namespace fspm::experiments {

// Below this many pairs in a group, a t-test finds only large differences: "like" then means
// little (the report says so).
inline constexpr std::size_t kFewPairs = 20;

// Markdown, starting with "## Findings"; empty when there is no t-test.
std::string findings_markdown(const Experiment& experiment, const std::vector<TTestRow>& tests);

}  // namespace fspm::experiments
