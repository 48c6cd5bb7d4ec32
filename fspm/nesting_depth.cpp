#include "fspm/nesting_depth.hpp"

#include "fspm/error.hpp"

namespace fspm {

std::string nesting_too_deep(int limit, std::string_view what) {
  return "nesting deeper than the limit of " + std::to_string(limit) + " levels (" +
         std::string(what) + ")";
}

void check_json_depth(std::string_view text, const std::string& file, int limit) {
  int depth = 0, line = 1, column = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) {
        throw ParseError(nesting_too_deep(limit, "JSON arrays and objects"), file, line, column);
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace fspm
