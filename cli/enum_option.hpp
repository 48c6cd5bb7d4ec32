#pragma once
// Command-line options whose values are the names of an enum: the text is turned into the enum
// value as the option is parsed, and a name outside the list is refused by CLI11 with the list.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

namespace fspm::cli {

// Adds `--name` to `app`, storing into `value` one of `kinds` given by its name `name_of(kind)`;
// the help lists the names and the default is `value`'s name.
template <typename Kind, std::size_t N>
CLI::Option* add_enum_option(CLI::App* app, const std::string& flag, Kind& value,
                             const Kind (&kinds)[N], std::string_view (*name_of)(Kind),
                             const std::string& help) {
  std::map<std::string, Kind> by_name;
  for (Kind k : kinds) by_name.emplace(std::string(name_of(k)), k);
  return app->add_option(flag, value, help)
      ->transform(CLI::CheckedTransformer(by_name))
      ->default_str(std::string(name_of(value)));
}

}  // namespace fspm::cli
