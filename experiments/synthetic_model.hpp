#pragma once
// Model kind "synthetic": a model without a file, for testing and benchmarking the runner. It
// builds a vertical chain of `nodes` internodes of length `length` and can be told to work, sleep
// or fail:
//   nodes = 10, length = 1.0   the chain
//   sleep_ms = 0               sleeps (checking the time limit every millisecond)
//   fail = 0                   1: the run throws ValueError("synthetic failure")
//   "x.NAME" = any             free parameters, recorded but otherwise ignored
#include <memory>

#include "experiments/model.hpp"

namespace fspm::experiments {

std::unique_ptr<Model> make_synthetic_model();

}  // namespace fspm::experiments
