#pragma once
// JSON allows an object to give a key twice and most parsers keep the last value silently
// (RFC 8259 4: "the names within an object SHOULD be unique"); in a file a person wrote, the
// second key is a mistake (a pasted block, a forgotten edit), so the project's readers refuse it
// as TOML does.
#include <string>
#include <string_view>

namespace fspm {

// Throws ParseError "duplicate key 'KEY' (first given on line N)" with the file, line and column
// of the second occurrence when an object of the valid JSON `text` gives a key twice. Keys are
// compared after their escapes are decoded ("a" and "\u0061" are the same key).
void check_json_duplicate_keys(std::string_view text, const std::string& file_name);

}  // namespace fspm
