#pragma once
// The light profile of `fspm report`: light against height in the crown for the report's typical
// trees (experiments/render_selection.hpp), drawn with VTK into DIR/figures/.
#include <string>
#include <vector>

#include "experiments/experiment.hpp"
#include "experiments/run_record.hpp"

namespace fspm::cli {

// One chart, one line per typical tree with leaf clusters (nodes of kind leaf with the attribute
// "translucency"): the mean light of the clusters' leaves (relative to the open sky, evaluated
// through the crown and the run's scene, environment/leaf_light.hpp) in ten layers from the
// lowest cluster to the highest, height above the tree's base on the vertical axis
// (environment/light_profile.hpp).
// Returns the Markdown showing it, "" when no tree has leaf light, or a note saying why it was
// left out.
std::string light_profile_figure(const experiments::Experiment& experiment,
                                 const std::vector<experiments::RunRecord>& runs,
                                 const std::string& dir);

}  // namespace fspm::cli
