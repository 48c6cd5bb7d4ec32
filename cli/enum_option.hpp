#pragma once
// Command-line options whose values are the names of an enum: the text is turned into the enum
// value as the option is parsed, and a name outside the list is refused by CLI11 with the list.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "fspm/closest_name.hpp"

namespace fspm::cli {

// Adds `--name` to `app`, storing into `value` one of `kinds` given by its name `name_of(kind)`;
// the help lists the names and the default is `value`'s name.
template <typename Kind, std::size_t N>
CLI::Option* add_enum_option(CLI::App* app, const std::string& flag, Kind& value,
                             const Kind (&kinds)[N], std::string_view (*name_of)(Kind),
                             const std::string& help) {
  std::map<std::string, Kind> by_name;
  std::vector<std::string> names;
  for (Kind k : kinds) {
    names.emplace_back(name_of(k));
    by_name.emplace(names.back(), k);
  }
  std::string choices;
  for (const std::string& n : names) choices += (choices.empty() ? "" : ", ") + n;
  // The text becomes the enum's number, which CLI11 then converts into the enum.
  CLI::Validator to_kind(
      [by_name, names](std::string& input) -> std::string {
        const auto it = by_name.find(input);
        if (it == by_name.end()) {
          return "'" + input + "' is not a choice" + closest_name_hint(input, names);
        }
        input = std::to_string(static_cast<std::underlying_type_t<Kind>>(it->second));
        return {};
      },
      "one of: " + choices);
  return app->add_option(flag, value, help)
      ->transform(to_kind)
      ->default_str(std::string(name_of(value)));
}

}  // namespace fspm::cli
