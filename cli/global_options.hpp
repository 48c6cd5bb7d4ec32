#pragma once
// Options of the whole command line (-v, -q, --memory-limit, --json, and how MTG files are read:
// --length-unit, --diameter-unit, --mtg-scale, --plant), accepted before the command and after it,
// and the check every option of every command shares (no empty values).
namespace CLI {
class App;
}

namespace fspm::cli {

// Adds -v/--verbose, -q/--quiet, --memory-limit and --json to the top-level app. Subcommands
// added afterwards take these options after their own ones too (CLI11's fallthrough). --json
// before the command sets that command's own --json flag; a command without one refuses it.
void add_global_options(CLI::App& app);

// Makes every option and argument of `app` and of all its subcommands refuse an empty value
// ("--seed ''"): CLI11 would otherwise convert it to the option's default or zero. Called once,
// after every command is registered.
void refuse_empty_values(CLI::App& app);

}  // namespace fspm::cli
