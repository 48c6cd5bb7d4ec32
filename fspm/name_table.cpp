#include "fspm/name_table.hpp"

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"

namespace fspm {

std::string expected_names_text(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += names[i];
  }
  return out;
}

std::string unknown_name_message(std::string_view noun, std::string_view name,
                                 const std::vector<std::string_view>& names) {
  // A name from a file can be anything: a long one is cut so the message stays one line.
  const std::string shown(name.substr(0, 60));
  std::string message =
      "unknown " + std::string(noun) + " '" + shown + "': expected " + expected_names_text(names);
  const std::vector<std::string> known(names.begin(), names.end());
  const std::string closest = closest_name(name, known);
  if (!closest.empty()) message += " (did you mean '" + closest + "'?)";
  return message;
}

void throw_unknown_name(std::string_view context, std::string_view noun, std::string_view name,
                        const std::vector<std::string_view>& names) {
  std::string message = unknown_name_message(noun, name, names);
  if (!context.empty()) message = std::string(context) + ": " + message;
  throw ValueError(message);
}

}  // namespace fspm
