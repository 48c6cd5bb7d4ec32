#pragma once
// The distributed runner (fspm run --mpi under mpirun): runs spread over MPI ranks with dynamic
// scheduling. Rank 0 opens the result database (same rules as the local runner: resume, shards,
// never overwrite), hands out run indices one at a time to whichever rank asks, runs models on one
// thread of its own meanwhile, and is the only writer. Every rank builds the same run plan from
// the same experiment file, so a run's parameters and seed are those of the local runner.
#include "experiments/runner.hpp"

namespace fspm::experiments {

// True when fspm was built with MPI.
bool mpi_available();

// Called on every rank (initializes and finalizes MPI when nobody else did). Each rank runs one
// run at a time (options.jobs is ignored: start one rank per core). The summary is complete on
// rank 0; on other ranks it counts that rank's runs. `is_root` tells the caller which it is.
RunnerSummary run_experiment_mpi(const Experiment& experiment, const Model& model,
                                 const RunnerOptions& options, bool& is_root);

}  // namespace fspm::experiments
