#pragma once
// Model kind "lsystem": parse a cpfg .l file (with #define overrides), derive it with the run's
// seed, interpret it with the turtle and measure the tree.
//   steps = N              derivation steps (default: the file's `derivation length:`)
//   "define.NAME" = v      replaces the #define NAME of the file by the text of v
//   "turtle.angle_deg" ... turtle settings over the view file: angle_deg, step,
//                          initial_line_width, line_width_increment, initial_elasticity,
//                          elasticity_increment
#include <memory>
#include <string>

#include "experiments/model.hpp"

namespace fspm::experiments {

// `view_file` empty: the .v file beside the .l file when there is one.
std::unique_ptr<Model> make_lsystem_model(const std::string& lsystem_file,
                                          const std::string& view_file, bool has_define_parameters);

}  // namespace fspm::experiments
