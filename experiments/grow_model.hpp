#pragma once
// Model kind "grow": the self-organizing growth model (environment/growth_model.hpp) in a scene,
// optionally followed by plastic adaptation, so that one experiment can hold Pirk's sets O, G and
// T (4.5.4):
//   preset = "A"|"B"|"C"   Pirk's tree types (default: the parameter file's, else A)
//   NAME = v               any key of a growth parameter file (years, alpha, phototropism, ...)
//   scene = "file.json"    the scene (default: model.scene; "open": sky and ground only)
//   set = "O"|"G"|"T"      O: grown without the scene's obstacles (its sky and ground only);
//                          G: grown in the scene (default);
//                          T: grown like O, then analysed and adapted to the scene
//   measure_regrowth = 1   set T: also grow the tree in the scene, timing it (regrow_seconds)
// The growth seed is the run's seed. Relative scene paths are resolved against the experiment
// file's folder.
#include <memory>
#include <string>

#include "experiments/model.hpp"

namespace fspm::experiments {

// `params_file` (may be empty) is a growth parameter TOML file; `scene_file` (may be empty) the
// default scene; `base_dir` resolves relative scene parameters.
std::unique_ptr<Model> make_grow_model(const std::string& params_file,
                                       const std::string& scene_file, const std::string& base_dir);

}  // namespace fspm::experiments
