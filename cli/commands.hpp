#pragma once
// Each subcommand family registers itself on the top-level app; main.cpp calls these in order.
namespace CLI {
class App;
}

namespace fspm::cli {

void add_tree_commands(CLI::App& app);
void add_environment_commands(CLI::App& app);
void add_experiment_commands(CLI::App& app);
void add_lsystem_commands(CLI::App& app);
void add_graphics_commands(CLI::App& app);
void add_greenlab_commands(CLI::App& app);
void add_evaluation_commands(CLI::App& app);
void add_adapt_commands(CLI::App& app);
void add_stages_commands(CLI::App& app);
void add_scan_commands(CLI::App& app);
void add_scene_commands(CLI::App& app);
// fspm decode (fspm-full: meshes).
void add_decode_commands(CLI::App& app);
// fspm crown (fspm-full, built with OpenImageIO).
void add_crown_commands(CLI::App& app);

// The commands that need the graphics and experiments libraries (run, compare, report, results,
// mesh, render, view, decode, crown): registered for real in fspm-full; in fspm only listed in
// --help.
void add_full_commands(CLI::App& app);
// In fspm: when the command line names one of those commands, replaces the process by fspm-full
// with the same arguments (throws IoError when it cannot); otherwise returns. In fspm-full:
// returns.
void hand_over_full_commands(int argc, char** argv);

}  // namespace fspm::cli
