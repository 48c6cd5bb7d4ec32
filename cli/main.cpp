// fspm: the command line. Exit codes: 0 success, 1 user error (one clear message on stderr),
// 2 internal error.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include "cli/commands.hpp"
#include "cli/global_options.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/signal_cleanup.hpp"

int main(int argc, char** argv) {
  // SIGINT and SIGTERM remove the temporaries of unfinished outputs before ending the process.
  fspm::install_signal_cleanup();
  fspm::cli::use_checked_standard_output();
  // Logs and progress go to stderr so stdout stays machine-readable.
  spdlog::set_default_logger(spdlog::stderr_color_mt("fspm"));
  spdlog::set_pattern("%^[%l]%$ %v");

  CLI::App app{"fspm: functional-structural plant modelling", "fspm"};
  // "fspm 0.1.0", then the commit and the optional parts of this build, a line each.
  app.set_version_flag("--version", std::string(FSPM_VERSION_TEXT));
  app.require_subcommand(1);
  // -v, -q, --memory-limit and --json, before the command or after it.
  fspm::cli::add_global_options(app);

  fspm::cli::add_tree_commands(app);
  fspm::cli::add_environment_commands(app);
  fspm::cli::add_lsystem_commands(app);
  fspm::cli::add_greenlab_commands(app);
  fspm::cli::add_evaluation_commands(app);
  fspm::cli::add_adapt_commands(app);
  fspm::cli::add_stages_commands(app);
  fspm::cli::add_scan_commands(app);
  fspm::cli::add_scene_commands(app);
  fspm::cli::add_full_commands(app);
  fspm::cli::refuse_empty_values(app);

  try {
    try {
      fspm::cli::hand_over_full_commands(argc, argv);
      app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
      const int code = app.exit(e);  // --help and --version print on stdout
      fspm::cli::finish_standard_output();
      return code == 0 ? 0 : 1;
    }
    fspm::cli::finish_standard_output();
  } catch (const fspm::Error& e) {
    std::cerr << "fspm: error: " << e.what() << '\n';
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // The system refused a path (a link loop, a permission): the user's file, not a bug.
    std::cerr << "fspm: error: " << (e.path1().empty() ? "" : e.path1().string() + ": ")
              << e.code().message() << '\n';
    return 1;
  } catch (const std::bad_alloc&) {
    // An allocation the estimates missed failed below the limit: still the user's budget.
    std::cerr << "fspm: error: out of memory below the memory limit of "
              << fspm::memory_text(static_cast<double>(fspm::memory_limit_bytes()))
              << " (--memory-limit): the machine or its limits gave less; give a lower "
                 "--memory-limit or free memory\n";
    return 1;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    std::cerr << "fspm: internal error: " << what.substr(0, fspm::kMaxErrorMessageLength)
              << (what.size() > fspm::kMaxErrorMessageLength ? " [...]" : "") << '\n';
    return 2;
  }
  return 0;
}
