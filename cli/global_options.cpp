#include "cli/global_options.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "fspm/length_unit.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/warning.hpp"

namespace fspm::cli {
namespace {

struct GlobalValues {
  int verbose = 0;
  bool quiet = false;
  bool json = false;
  std::string memory_limit;
  // How MTG files are read, by every command that reads one (docs/formats.md, "MTG").
  std::string length_unit;
  std::string diameter_unit;
  int mtg_scale = -1;
  std::string plant;
};

MtgTreeOptions mtg_options(const GlobalValues& v) {
  MtgTreeOptions o;
  if (!v.length_unit.empty()) o.length_unit = length_unit_from_name(v.length_unit, "--length-unit");
  if (!v.diameter_unit.empty()) {
    o.diameter_unit = length_unit_from_name(v.diameter_unit, "--diameter-unit");
  }
  o.scale = v.mtg_scale;
  o.plant = v.plant;
  return o;
}

void add_mtg_options(CLI::App& app, GlobalValues& values) {
  app.add_option("--length-unit", values.length_unit,
                 "Unit of lengths and coordinates in MTG files: m, dm, cm or mm (default m)");
  app.add_option("--diameter-unit", values.diameter_unit,
                 "Unit of diameters and radii in MTG files: m, dm, cm or mm (default: the "
                 "length unit)");
  app.add_option("--mtg-scale", values.mtg_scale,
                 "Scale of an MTG file whose entities become the tree's nodes (default: the "
                 "finest with geometry)")
      ->check(CLI::Range(0, 1000));
  app.add_option("--plant", values.plant,
                 "Keep one plant of a multi-plant MTG file: its label (P2) or number (2)");
}

// The command that runs: the deepest subcommand on the command line so far, and its words
// ("tree info"); null when no command was named.
CLI::App* chosen_command(const CLI::App& app, std::string& words) {
  CLI::App* command = nullptr;
  for (auto named = app.get_subcommands(); !named.empty(); named = command->get_subcommands()) {
    command = named.front();
    words += (words.empty() ? "" : " ") + command->get_name();
  }
  return command;
}

// One line, like the other user errors, with the help to read: "fspm: error: --seed: expected
// a number in [0, ...], got '' (see fspm scan --help)".
std::string failure_line(const CLI::App* app, const CLI::Error& e) {
  std::string words;
  chosen_command(*app, words);
  std::string what = e.what();
  // "fspm frobnicate": CLI11 says a subcommand is required; name the word it did not know.
  const std::vector<std::string> left = app->remaining(true);
  if (what.starts_with("A subcommand is required") && !left.empty()) {
    what = "unknown command '" + left.front().substr(0, 80) + "'";
  }
  return "fspm: error: " + what + " (see fspm " + (words.empty() ? "" : words + " ") + "--help)\n";
}

// --json given before the command (or after a command group such as `tree`) lands on the
// top-level flag: hand it to the command's own --json.
void pass_json_to_command(CLI::App& app) {
  std::string words;
  CLI::App* command = chosen_command(app, words);
  CLI::Option* json = command == nullptr ? nullptr : command->get_option_no_throw("--json");
  if (json == nullptr) {
    throw ValueError("--json: 'fspm " + words + "' has no JSON output");
  }
  if (json->count() == 0) {
    json->add_result("true");
    json->run_callback();
  }
}

}  // namespace

void add_global_options(CLI::App& app) {
  auto values = std::make_shared<GlobalValues>();
  app.add_flag("-v,--verbose", values->verbose, "More log output on stderr (repeat for more)");
  app.add_flag("-q,--quiet", values->quiet, "Only warnings and errors on stderr");
  app.add_option("--memory-limit", values->memory_limit,
                 "Largest memory a command may plan to use: 512M, 2G ... (default: half of the "
                 "physical memory, or of the ulimit or cgroup limit when lower)");
  add_mtg_options(app, *values);
  app.add_flag("--json", values->json,
               "Machine-readable JSON on stdout, for the commands that offer it (same as the "
               "command's own --json)");
  // Runs once parsing is complete and before the command's callback.
  app.parse_complete_callback([values, &app] {
    set_verbosity(values->quiet ? 0 : (values->verbose > 0 ? 2 : 1));
    if (!values->memory_limit.empty()) {
      set_memory_limit_bytes(parse_memory_size(values->memory_limit, "--memory-limit"));
    }
    set_default_mtg_tree_options(mtg_options(*values));
    if (values->json) pass_json_to_command(app);
  });
  app.fallthrough();
  set_warning_handler([](const std::string& message) { spdlog::warn("{}", message); });
  app.failure_message(failure_line);
}

void refuse_empty_values(CLI::App& app) {
  static const CLI::Validator non_empty(
      [](std::string& text) -> std::string {
        return text.empty() ? "expected a value, got an empty string" : std::string();
      },
      "");
  for (CLI::Option* option : app.get_options()) {
    // Flags take no value; their results are filled in by CLI11, never empty.
    if (option->get_type_size_max() > 0) option->check(non_empty);
  }
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    refuse_empty_values(*command);
  }
}

}  // namespace fspm::cli
