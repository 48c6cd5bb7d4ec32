#pragma once
// Shared helpers of the subcommands: machine-readable output on stdout, logs on stderr.
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace fspm::cli {

// Prints one JSON document on stdout (pretty, newline-terminated).
void print_json(const nlohmann::json& document);

// Verbosity from -v/-q: 0 quiet, 1 normal, 2 verbose. Logs go to stderr through spdlog.
void set_verbosity(int level);
int verbosity();

}  // namespace fspm::cli
