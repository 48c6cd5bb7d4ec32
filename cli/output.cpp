#include "cli/output.hpp"

#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <system_error>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm::cli {
namespace {
int g_verbosity = 1;

std::string bound_text(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

CLI::Validator range_check(double low, double high, bool low_inclusive) {
  const std::string range =
      (low_inclusive ? "[" : "(") + bound_text(low) + ", " + bound_text(high) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const auto v = parse_number(text);
        if (v && (low_inclusive ? *v >= low : *v > low) && *v <= high) return {};
        const std::string shown = text.size() > 40 ? text.substr(0, 40) + "..." : text;
        return "expected a number in " + range + ", got '" + shown + "'";
      },
      "in " + range);
}

}  // namespace

CLI::Validator number_in(double low, double high) { return range_check(low, high, true); }
CLI::Validator positive_number(double high) { return range_check(0.0, high, false); }

void print_json(const nlohmann::json& document) { std::cout << document.dump(2) << '\n'; }

void finish_standard_output() {
  errno = 0;
  std::cout.flush();
  // std::cout writes through C stdio (synchronised), whose error flag also records earlier
  // failures; flushing again sets errno to the reason when the failure persists.
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout) != 0;
  if (!failed) return;
  const int reason = errno;
  std::clearerr(stdout);
  std::cout.clear();
  throw IoError("cannot write: " +
                    (reason != 0 ? std::generic_category().message(reason) : "write failed"),
                "standard output");
}

void set_verbosity(int level) {
  g_verbosity = level;
  spdlog::set_level(level <= 0 ? spdlog::level::warn
                               : (level == 1 ? spdlog::level::info : spdlog::level::debug));
}

int verbosity() { return g_verbosity; }

}  // namespace fspm::cli
