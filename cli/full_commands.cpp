// fspm-full: the commands that need the graphics (VTK, OpenImageIO) and experiments (SQLite, MPI)
// libraries, registered for real. fspm lists the same commands and hands them over
// (forwarded_commands.cpp).
#include <CLI/CLI.hpp>

#include "cli/commands.hpp"
#include "cli/full_command_list.hpp"
#include "fspm/error.hpp"

namespace fspm::cli {

void add_full_commands(CLI::App& app) {
  add_experiment_commands(app);
  add_graphics_commands(app);
  add_decode_commands(app);
#ifdef FSPM_HAVE_CROWN
  add_crown_commands(app);
#else
  app.add_subcommand(kCrownCommand.name, kCrownCommand.description)->callback([] {
    throw ValueError("fspm was built without OpenImageIO (FSPM_WITH_VTK=OFF): no crown command");
  });
#endif
}

void hand_over_full_commands(int /*argc*/, char** /*argv*/) {}  // fspm-full runs them itself

}  // namespace fspm::cli
