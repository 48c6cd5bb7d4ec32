#include "experiments/run_files.hpp"

#include <cstdio>

#include "fspm/error.hpp"

namespace fspm::experiments {

std::string run_file_path(std::size_t run, std::string_view extension) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "runs/run-%07zu.", run);
  return buf + std::string(extension);
}

void check_run_file_writers(const Experiment& experiment, const RunFileWriters& writers) {
  for (const KeptFile kind : experiment.keep) {
    if (kind == KeptFile::kTree || writers.contains(kind)) continue;
    throw ValueError("outputs.keep: '" + std::string(kept_file_name(kind)) +
                         "' files need a writer that this program does not install (fspm run "
                         "writes meshes, and images when built with VTK; keep \"tree\" and use "
                         "fspm mesh or fspm render on the kept trees)",
                     experiment.path, experiment.keep_line);
  }
}

}  // namespace fspm::experiments
