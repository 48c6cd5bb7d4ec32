#pragma once
// The data of the HTML report (cli/html_report.hpp) as JSON for its data.js: every run, the
// metrics with their units and the comparison pairs, in columns (one array per field) so that a
// few thousand runs stay small. Non-finite numbers become null; seeds are text, since JavaScript
// numbers hold integers only up to 2^53.
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "cli/report_light_profile.hpp"
#include "experiments/comparisons.hpp"
#include "experiments/model_kind.hpp"
#include "experiments/results_db.hpp"

namespace fspm::cli {

// {"run": [..], "point": [..], "seed": ["..."], "status": ["ok", ..], "parameters": {name:
// [..]}, "metrics": {name: [..]}}: numbers stay numbers, text parameters text.
nlohmann::json html_runs_json(const experiments::ExperimentInfo& info,
                              const std::vector<experiments::RunRecord>& runs);

// [{"name", "unit", "timing"}] in the database's order (experiments/report.hpp metric_unit).
nlohmann::json html_metrics_json(const experiments::ExperimentInfo& info,
                                 std::optional<experiments::ModelKind> model_kind);

// {"comparison": [..], "group": [..], "run_a": [..], "run_b": [..], "distance": [..]}.
// "distance" holds the distance the t-tests compare (`scale`, the experiment's distance.tested),
// "raw_distance" the raw one.
nlohmann::json html_pairs_json(const experiments::ComparisonResults& results,
                               experiments::DistanceScale scale);

// [{"run", "group", "height_m": [..], "mean_light": [..], "clusters": [..]}], one per tree of
// light_profiles(), its layers bottom to top: the numbers of report.md's light profile.
nlohmann::json html_light_profiles_json(const LightProfiles& profiles);

}  // namespace fspm::cli
