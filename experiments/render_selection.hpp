#pragma once
// The trees `fspm report` renders ([report] of the experiment file, RenderSpec): one typical run
// per group, the one whose metric is the group's median, so a figure shows a representative
// tree rather than the first or an extreme one.
#include <cstddef>
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/run_record.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::experiments {

struct RenderChoice {
  std::size_t run = 0;
  std::string group;    // "set = T, years = 30" (the `by` values), "all runs" without `by`
  std::string caption;  // run, seed, every swept value and the metric
};

// The runs to render, in grid order of their groups. Groups: the successful runs matching
// `where`, by their `by` values (default: every swept parameter), in order of first appearance;
// from each, the run with the lower median of the metric (ties: the lower run index; runs
// without the metric come last); when there are G groups and N = `renders` < G, groups
// round(i (G - 1) / (N - 1)) for i = 0..N-1, the first and the last included.
std::vector<RenderChoice> select_renders(const Experiment& experiment,
                                         const std::vector<RunRecord>& runs);

// The tree of a recorded run: its kept tree file (relative to `dir`) when there is one, else the
// model run again with the recorded parameters and seed (runs are deterministic given both). Throws
// ValueError when the model gives no tree, and the model's own errors.
TreeGraph recorded_run_tree(const Experiment& experiment, const RunRecord& record,
                            const std::string& dir);

}  // namespace fspm::experiments
