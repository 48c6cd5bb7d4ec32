#pragma once
// Text bound for a terminal line: error messages and warnings pass through one_line(), so that a
// message stays one line and cannot drive the terminal, whatever a file name holds.
#include <string>
#include <string_view>

namespace fspm {

// `text` with its control characters (a newline or an escape sequence in a file name) written
// as C escapes (\n, \r, \x1b); tabs and every other byte kept.
std::string one_line(std::string_view text);

}  // namespace fspm
