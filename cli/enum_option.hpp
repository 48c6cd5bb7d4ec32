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
#include "fspm/name_table.hpp"

namespace fspm::cli {

// The transform that turns a name into the enum's number (which CLI11 then converts into the
// enum), refusing other names with the closest one.
template <typename Kind>
CLI::Validator enum_transform(const std::vector<std::string>& names,
                              const std::vector<Kind>& kinds) {
  std::map<std::string, Kind> by_name;
  std::string choices;
  for (std::size_t i = 0; i < names.size(); ++i) {
    by_name.emplace(names[i], kinds[i]);
    choices += (i ? ", " : "") + names[i];
  }
  return CLI::Validator(
      [by_name, names](std::string& input) -> std::string {
        const auto it = by_name.find(input);
        if (it == by_name.end()) {
          return "'" + input + "' is not a choice" + closest_name_hint(input, names);
        }
        input = std::to_string(static_cast<std::underlying_type_t<Kind>>(it->second));
        return {};
      },
      "one of: " + choices);
}

// Adds `--name` to `app`, storing into `value` one of `kinds` (any range of the enum) given by
// its name `name_of(kind)`; the help lists the names and the default is `value`'s name.
template <typename Kind, typename Kinds>
CLI::Option* add_enum_option(CLI::App* app, const std::string& flag, Kind& value,
                             const Kinds& kinds, std::string_view (*name_of)(Kind),
                             const std::string& help) {
  std::vector<std::string> names;
  std::vector<Kind> values;
  for (Kind k : kinds) {
    names.emplace_back(name_of(k));
    values.push_back(k);
  }
  return app->add_option(flag, value, help)
      ->transform(enum_transform(names, values))
      ->default_str(std::string(name_of(value)));
}

// The same for an enum with a NameTable: the help is `help` followed by the table's names and
// what each means ("Cost model: topological (every edit costs 1), absolute (...)").
template <typename Kind, std::size_t N>
CLI::Option* add_enum_option(CLI::App* app, const std::string& flag, Kind& value,
                             const NameTable<Kind, N>& table, const std::string& help) {
  std::vector<std::string> names;
  std::vector<Kind> values;
  for (const NamedValue<Kind>& e : table.entries()) {
    names.emplace_back(e.name);
    values.push_back(e.value);
  }
  return app->add_option(flag, value, help + ": " + table.help())
      ->transform(enum_transform(names, values))
      ->default_str(std::string(table.name(value)));
}

}  // namespace fspm::cli
