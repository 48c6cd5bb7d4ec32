#pragma once
// Model kind "adapt": plastic adaptation (Pirk 4.3-4.4) of one given tree file to a scene, so that
// a sweep can move obstacles, the tree or the analysis parameters around a tree that was grown (or
// measured) elsewhere:
//   scene = "file.json"      the scene (default: model.scene; "open": no obstacles)
//   tree_x_m, tree_y_m       where the tree's base stands in the scene (default 0, 0)
//   skeleton_radius_m, min_cluster_radius_m, gamma0, pruning_strength, reference_percentile,
//   temporal_pruning (0/1), phototropism, gravitropism, light_directions, light_significance
//                            the analysis parameters (environment/tree_analysis.hpp)
// The tree is analysed once per distinct set of analysis parameters and the analysis is shared by
// every run that uses it: a new scene or position re-adapts without re-analysing (Pirk 4.4.3).
// The run's seed is not used (the adaptation is deterministic).
#include <memory>
#include <string>

#include "experiments/model.hpp"

namespace fspm::experiments {

// `tree_file` is read at once (a bad file is reported before any run); `scene_file` (may be empty)
// is the default scene; `base_dir` resolves relative scene parameters.
std::unique_ptr<Model> make_adapt_model(const std::string& tree_file, const std::string& scene_file,
                                        const std::string& base_dir);

}  // namespace fspm::experiments
