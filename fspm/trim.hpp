#pragma once
// Text without the blanks around it: spaces, tabs and carriage returns (the '\r' of a CRLF line
// read by a reader that splits at '\n'). One helper for the line-oriented readers.
#include <string_view>

namespace fspm {

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

}  // namespace fspm
