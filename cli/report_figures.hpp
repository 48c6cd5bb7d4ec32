#pragma once
// The figures of `fspm report` (docs/experiments.md), drawn with VTK into DIR/figures/: each
// metric against each swept parameter, box plots of the comparison distances with the number of
// pairs per box, and renders of typical trees at one common scale with a scale bar and the
// obstacles they grew beside. Each returns the Markdown that shows its figures, or a note saying
// why they were left out (no X display, a file that could not be written, ...).
#include <string>
#include <vector>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/results_db.hpp"

namespace fspm::cli {

// One chart per swept parameter with at least two values and per metric: the mean over the
// successful runs with each value (solid, dots) and mean ± sample standard deviation (dashed),
// experiments/sweep_summary.hpp; text values evenly spaced and labelled.
std::string sweep_figures(const experiments::Experiment& experiment,
                          const experiments::ExperimentInfo& info,
                          const std::vector<experiments::RunRecord>& runs, const std::string& dir);

// One box plot per comparison group, the comparisons side by side, each box labelled with its
// number of pairs.
std::string comparison_figures(const experiments::Experiment& experiment,
                               const experiments::ComparisonResults& results,
                               const std::string& dir);

// The typical trees of experiments/render_selection.hpp, each with the obstacles of its scene
// (recorded_run_scene, cut to the region around the tree), all in a parallel projection at the
// scale that fits the largest, so sizes compare across pictures, with a scale bar.
std::string tree_renders(const experiments::Experiment& experiment,
                         const std::vector<experiments::RunRecord>& runs, const std::string& dir);

}  // namespace fspm::cli
