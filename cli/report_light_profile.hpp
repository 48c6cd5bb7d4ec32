#pragma once
// The light profile of `fspm report`: light against height in the crown for the report's typical
// trees (experiments/render_selection.hpp), drawn with VTK into DIR/figures/ for report.md, and
// as numbers for the HTML report's plot (cli/html_report.hpp).
#include <cstddef>
#include <string>
#include <vector>

#include "environment/light_profile.hpp"
#include "experiments/experiment.hpp"
#include "experiments/run_record.hpp"

namespace fspm::cli {

// One typical tree's profile: the mean light of its leaf clusters per layer, bottom to top.
struct TreeLightProfile {
  std::size_t run = 0;
  std::string group;
  std::vector<environment::LightLayer> layers;
};

struct LightProfiles {
  std::vector<TreeLightProfile> trees;  // the typical trees with leaf clusters, in group order
  std::vector<std::string> notes;       // why a tree was left out
};

// For each typical tree with leaf clusters (nodes of kind leaf with the attribute
// "translucency"): the mean light of the clusters' leaves (relative to the open sky, evaluated
// through the crown and the run's scene, environment/leaf_light.hpp) in ten layers from the
// lowest cluster to the highest (environment/light_profile.hpp).
LightProfiles light_profiles(const experiments::Experiment& experiment,
                             const std::vector<experiments::RunRecord>& runs,
                             const std::string& dir);

// The paragraph under the section "Light in the crown" saying what the profile shows.
std::string light_profile_explanation();

// One chart of light_profiles(), one line per tree, height above the tree's base on the
// vertical axis. Returns the Markdown showing it, "" when no tree has leaf light, or a note
// saying why it was left out.
std::string light_profile_figure(const experiments::Experiment& experiment,
                                 const std::vector<experiments::RunRecord>& runs,
                                 const std::string& dir);

}  // namespace fspm::cli
