#include "fspm/toml_text.hpp"

#include "fspm/error.hpp"

namespace fspm {

toml::table parse_toml_text(std::string_view text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw ParseError("expected valid TOML (" + std::string(e.description()) + ")", file,
                     static_cast<int>(e.source().begin.line),
                     static_cast<int>(e.source().begin.column));
  }
}

int toml_line(const toml::node& node) { return static_cast<int>(node.source().begin.line); }
int toml_column(const toml::node& node) { return static_cast<int>(node.source().begin.column); }

}  // namespace fspm
