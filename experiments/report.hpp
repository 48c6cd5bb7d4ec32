#pragma once
// The Markdown report of a result database (fspm report): the introduction (report_intro.hpp), the
// run counts, tables of mean and standard deviation of every metric per parameter point (over its
// successful replicates), what the plants did and the timings in separate tables, marginal means
// per swept parameter (sweep_summary.hpp), and the failed runs.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/model_kind.hpp"
#include "experiments/results_db.hpp"

namespace fspm::experiments {

// The unit of lengths of a model kind: "model units" for L-system plants (the L-system's own
// units), "m" for every other model.
std::string length_unit(std::optional<ModelKind> model_kind);

// The unit of a metric as the report prints it ("m", "m^2", "count", "s", ...), the catalogue's
// "length" written as the model's length unit; empty for an unknown metric.
std::string metric_unit(const std::string& metric, std::optional<ModelKind> model_kind);

// The title, `introduction`, run counts, the plant metrics per point and their marginal means,
// and the failed runs. The timings (metrics in seconds) are left to timings_markdown, which a
// report puts last: a botanist reads the plants first, whoever plans the next sweep the times.
std::string markdown_report(const ExperimentInfo& info, const std::vector<RunRecord>& runs,
                            const std::string& introduction = "");

// "## Timings": seconds of computing time per parameter point and their marginal means; empty
// when no timing metric was recorded.
std::string timings_markdown(const ExperimentInfo& info, const std::vector<RunRecord>& runs);

// The experiment's [[table]]s: mean ± standard deviation of the listed metrics over the
// successful runs matching `where`, one row per combination of the `by` values (Pirk Table 4.2
// is such a table: nodes, growth and adaptation time per age).
std::string summary_tables_markdown(const Experiment& experiment,
                                    const std::vector<RunRecord>& runs);

}  // namespace fspm::experiments
