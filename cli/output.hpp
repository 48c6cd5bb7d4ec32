#pragma once
// Shared helpers of the subcommands: machine-readable output on stdout, logs on stderr.
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace CLI {
class Validator;
}

namespace fspm::cli {

// Prints one JSON document on stdout (pretty, newline-terminated).
void print_json(const nlohmann::json& document);

// Flushes standard output and throws IoError naming "standard output" and the system's reason
// (e.g. "No space left on device", "Bad file descriptor") when any write to it failed. Called
// once, where the command line ends, rather than after each print.
void finish_standard_output();

// Checks of numeric options with short messages ("expected a number in [0, 1000], got '-1'"),
// refusing nan and inf: in [low, high], or in (0, high] for positive_number.
CLI::Validator number_in(double low, double high);
// Seeds are 64-bit; this is the largest double below 2^63.
inline constexpr double kMaxSeed = 9223372036854774784.0;
CLI::Validator positive_number(double high);

// Verbosity from -v/-q: 0 quiet, 1 normal, 2 verbose. Logs go to stderr through spdlog.
void set_verbosity(int level);
int verbosity();

}  // namespace fspm::cli
