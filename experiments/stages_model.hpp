#pragma once
// Model kind "stages": developmental stages (Pirk chapter 5) of one given static tree, so that a
// sweep can vary the stage time and the reverse-growth parameters:
//   t                  stage time in [0, 1] (1: the given tree; default 1)
//   season_years       > 0: t is remapped over that many seasons by Pirk eq. 5.11 (default 0)
//   continuation       "thickest" (default) or "least_deviation" (Pirk 5.2.2)
//   rigid_tip_count, pipe_exponent, same_level_tolerance   the analysis parameters
//                      (stages/developmental_model.hpp)
// The tree is analysed once per distinct set of analysis parameters, shared by every run that
// uses it; a run only computes its stage. The run's seed is not used (stages are deterministic).
// Metrics: the stage's tree metrics, analysis_seconds and stage_seconds.
#include <memory>
#include <string>

#include "experiments/model.hpp"

namespace fspm::experiments {

// `tree_file` is read at once, so a bad file is reported before any run.
std::unique_ptr<Model> make_stages_model(const std::string& tree_file);

}  // namespace fspm::experiments
