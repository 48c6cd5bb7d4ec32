#pragma once
// Model kind "greenlab": a GreenLab plant description (TOML, docs/greenlab.md) simulated for a
// number of cycles with the run's seed (GL2 draws), GL1 functioning when the description enables
// it, then reconstructed into a tree and measured.
//   cycles = N           growth cycles (default: the description's)
//   NAME = v             any numeric parameter of greenlab::set_parameter ("resistance",
//                        "age.2.leaf_sink", ...)
// Adds the metric "biomass": total GL1 production including the seed, sum of Q(n) for
// n = 0..cycles (mass unit of the description); not given without GL1.
#include <memory>
#include <string>

#include "experiments/model.hpp"

namespace fspm::experiments {

std::unique_ptr<Model> make_greenlab_model(const std::string& plant_file);

}  // namespace fspm::experiments
