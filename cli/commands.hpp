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

}  // namespace fspm::cli
