// fspm-full: the commands that need the graphics (VTK, OpenImageIO) and experiments (SQLite, MPI)
// libraries, registered for real. fspm lists the same commands and hands them over
// (forwarded_commands.cpp).
#include "cli/commands.hpp"

namespace fspm::cli {

void add_full_commands(CLI::App& app) {
  add_experiment_commands(app);
  add_graphics_commands(app);
}

void hand_over_full_commands(int /*argc*/, char** /*argv*/) {}  // fspm-full runs them itself

}  // namespace fspm::cli
