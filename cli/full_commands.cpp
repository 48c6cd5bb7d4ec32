// fspm-full: the commands that need the graphics (VTK, OpenImageIO) and experiments (SQLite, MPI)
// libraries, registered for real. fspm lists the same commands and hands them over
// (forwarded_commands.cpp).
#include <CLI/CLI.hpp>
#include <string>

#include "cli/commands.hpp"
#include "cli/full_command_list.hpp"
#include "cli/manual.hpp"
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
  // The manual is written from this app, which has every command with its options; the version
  // is the first line of --version ("fspm 0.1.0"), without the commit, so the pages change only
  // with the release.
  const std::string version_text = FSPM_VERSION_TEXT;
  add_manual_command(app, version_text.substr(0, version_text.find('\n')));
}

void hand_over_full_commands(int /*argc*/, char** /*argv*/) {}  // fspm-full runs them itself

}  // namespace fspm::cli
