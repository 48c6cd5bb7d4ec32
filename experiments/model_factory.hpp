#pragma once
// The model an experiment names, checked against every parameter value it will get before any
// run starts.
#include <memory>

#include "experiments/experiment.hpp"
#include "experiments/model.hpp"
#include "experiments/run_plan.hpp"

namespace fspm::experiments {

// Throws ValueError naming the experiment file and line for an unknown kind, a missing model file,
// an unknown parameter or a bad value; parse errors of the model file propagate.
std::unique_ptr<Model> make_model(const Experiment& experiment);
void check_experiment(const Experiment& experiment, const Model& model, const RunPlan& plan);

}  // namespace fspm::experiments
