#pragma once
// Parsing TOML configuration text (toml++), with the one error every TOML reader gives for a
// malformed file: ParseError naming the file, line and column.
#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace fspm {

// The document in `text`; `file` names it in errors ("<string>" for text not from a file).
toml::table parse_toml_text(std::string_view text, const std::string& file);

// The 1-based line and column where `node` was read (0 for nodes made in code).
int toml_line(const toml::node& node);
int toml_column(const toml::node& node);

}  // namespace fspm
