#include "cli/output.hpp"

#include <spdlog/spdlog.h>

#include <iostream>
#include <nlohmann/json.hpp>

namespace fspm::cli {
namespace {
int g_verbosity = 1;
}

void print_json(const nlohmann::json& document) { std::cout << document.dump(2) << '\n'; }

void set_verbosity(int level) {
  g_verbosity = level;
  spdlog::set_level(level <= 0 ? spdlog::level::warn
                               : (level == 1 ? spdlog::level::info : spdlog::level::debug));
}

int verbosity() { return g_verbosity; }

}  // namespace fspm::cli
