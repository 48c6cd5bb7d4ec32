#pragma once
// The trees `fspm report` renders ([report] of the experiment file, RenderSpec): one typical run
// per group, the one whose metric is the group's median, so a figure shows a representative
// tree rather than the first or an extreme one.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "environment/scene.hpp"
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

// The obstacles a recorded run's tree stood beside, in the tree's coordinates, for drawing them
// with it: the run's scene (its `scene` parameter, relative to the experiment file, else
// model.scene) for the grow model's sets G and T, and for the adapt model moved by -tree_x_m,
// -tree_y_m as the model moves it. nullopt for set O (grown without obstacles), scene "open", no
// scene, and the other model kinds. Throws the scene reader's errors.
std::optional<environment::Scene> recorded_run_scene(const Experiment& experiment,
                                                     const RunRecord& record);

}  // namespace fspm::experiments
