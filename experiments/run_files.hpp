#pragma once
// Files kept per run ([outputs] keep, docs/experiments.md). The runner writes "tree" itself;
// "mesh" and "image" need graphics, which this library does not depend on, so the program that
// runs the experiment installs writers for them (fspm run does; the Python module does not).
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "experiments/experiment.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::experiments {

// Writes the file of one kind for run `run` from the run's tree under `out_dir` (its runs/
// folder exists), atomically, and returns the path relative to `out_dir` (run_file_path). Called
// from several worker threads at once (and on every MPI rank): must be thread-safe. Throws on
// failure; the run is then recorded with status error and the message.
using RunFileWriter =
    std::function<std::string(const TreeGraph& tree, std::size_t run, const std::string& out_dir)>;
// By kind: KeptFile::kMesh, KeptFile::kImage.
using RunFileWriters = std::map<KeptFile, RunFileWriter>;

// "runs/run-0000042.glb": the path of run 42's file with that extension, relative to the output
// directory.
std::string run_file_path(std::size_t run, std::string_view extension);

// Throws ValueError naming outputs.keep and its line when the experiment keeps a kind other than
// a tree that has no writer, before any run starts.
void check_run_file_writers(const Experiment& experiment, const RunFileWriters& writers);

}  // namespace fspm::experiments
