#pragma once
// Shared helpers of the subcommands: machine-readable output on stdout, logs on stderr.
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <nlohmann/json_fwd.hpp>
#include <string>

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace fspm::cli {

// Prints one JSON document on stdout (pretty, newline-terminated).
void print_json(const nlohmann::json& document);

// JSON as text. Names read from input files (MTG features, attributes) may hold bytes that are
// not UTF-8 (a Latin-1 file); they are written as U+FFFD instead of ending the command.
std::string json_text(const nlohmann::json& value, int indent = -1);

// A JSON value as people read it: floating-point numbers to four significant digits
// (format_significant), arrays as "[a, b]", integers, booleans and strings as JSON writes them.
// The --json form of the same command keeps every digit.
std::string human_text(const nlohmann::json& value);

// Routes std::cout through a buffer that remembers the system's reason of a failed write; then
// finish_standard_output() flushes and throws IoError naming "standard output" and that reason
// ("No space left on device", "Bad file descriptor") when any write failed. Both are called
// once, where the command line starts and ends, rather than after each print.
void use_checked_standard_output();
void finish_standard_output();

// Runs a command whose files and printed report are one result: the files it writes stay in
// temporaries (fspm::OutputTransaction) until its report has gone out on standard output, so a
// report that cannot be written (`--json >/dev/full`, a closed stdout) fails the command and leaves
// none of its files. Not for commands that keep the finished parts of a long job (run, stages) or
// read back what they wrote (report).
void run_reporting_command(const std::function<void()>& command);

// Throws ValueError naming `output` when it is, or resolves to (a link, "./", ".."), one of
// `inputs`: the command would replace a file it reads. Empty names are skipped.
void refuse_overwriting_input(const std::string& output, std::initializer_list<std::string> inputs);

// Throws ValueError when the outputs `first` (of option `first_option`) and `second` (of
// `second_option`) are, or resolve to, the same file, existing or not: one would replace the other.
// Empty names are skipped.
void refuse_same_output(const std::string& first, std::string_view first_option,
                        const std::string& second, std::string_view second_option);

// Checks of numeric options with short messages ("expected a number in [0, 1000], got '-1'"),
// refusing nan and inf: in [low, high], or in (0, high] for positive_number.
CLI::Validator number_in(double low, double high);
// Seeds are 64-bit; this is the largest double below 2^63.
inline constexpr double kMaxSeed = 9223372036854774784.0;
CLI::Validator positive_number(double high);

// The tree file formats a --format option takes.
inline constexpr const char* kTreeFormats = "tree, treeb, nwk or mtg (default: from the extension)";
// --format of a command that reads tree files.
void add_input_format_option(CLI::App* command, std::string& format);

// Verbosity from -v/-q: 0 quiet, 1 normal, 2 verbose. Logs go to stderr through spdlog.
void set_verbosity(int level);
int verbosity();

}  // namespace fspm::cli
