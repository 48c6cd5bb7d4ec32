#pragma once
// The manual pages (fspm.1 and fspm-COMMAND.1, one per command) and the bash completion script,
// written from the command line's own CLI11 definitions, so they list exactly the commands and
// options the program accepts. The build runs `fspm-full write-manual` (a hidden command) and
// installs what it writes (cli/CMakeLists.txt).
#include <filesystem>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace fspm::cli {

// The commands a user sees under `app` (hidden ones, as write-manual itself, left out), in the
// order of --help.
std::vector<const CLI::App*> visible_commands(const CLI::App& app);

// The roff text of fspm.1 (`app` is the top-level app) or of fspm-COMMAND.1 (`app` is one of its
// commands, with the commands under it as sections). `version` goes into the page footer.
std::string man_page(const CLI::App& app, const std::string& version);

// A bash completion script for `fspm` and `fspm-full`: commands, their subcommands and options.
std::string bash_completion(const CLI::App& app);

// Writes fspm.1 and one fspm-COMMAND.1 per command into `man_dir`, and the completion script to
// `completion_file`. Throws IoError when a file cannot be written.
void write_manual(const CLI::App& app, const std::string& version,
                  const std::filesystem::path& man_dir,
                  const std::filesystem::path& completion_file);

// Registers the hidden `write-manual --man-dir DIR --bash-completion FILE` on the top-level app.
void add_manual_command(CLI::App& app, const std::string& version);

}  // namespace fspm::cli
