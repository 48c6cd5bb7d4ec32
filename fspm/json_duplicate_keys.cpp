#include "fspm/json_duplicate_keys.hpp"

#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "fspm/error.hpp"

namespace fspm {
namespace {

struct Place {
  int line = 1;
  int column = 1;
};

// One open object or array: for objects, the keys given so far and where.
struct Scope {
  bool object = false;
  std::map<std::string, int> keys;  // decoded key -> its line
};

// The decoded text of the JSON string whose quoted form (quotes included) is `quoted`.
std::string decoded(std::string_view quoted) {
  if (quoted.find('\\') == std::string_view::npos) {
    return std::string(quoted.substr(1, quoted.size() - 2));
  }
  return nlohmann::json::parse(quoted).get<std::string>();
}

// Whether the next character after `from` that is not white space is ':'.
bool followed_by_colon(std::string_view text, std::size_t from) {
  while (from < text.size() &&
         (text[from] == ' ' || text[from] == '\t' || text[from] == '\n' || text[from] == '\r')) {
    ++from;
  }
  return from < text.size() && text[from] == ':';
}

}  // namespace

void check_json_duplicate_keys(std::string_view text, const std::string& file_name) {
  std::vector<Scope> scopes;
  Place at;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      const Place start = at;
      std::size_t end = i + 1;
      while (end < text.size() && text[end] != '"') end += text[end] == '\\' ? 2 : 1;
      if (end >= text.size()) return;  // not valid JSON: the parser reports it
      const std::string_view quoted = text.substr(i, end - i + 1);
      at.column += static_cast<int>(quoted.size()) - 1;  // strings hold no raw line break
      i = end;
      if (scopes.empty() || !scopes.back().object || !followed_by_colon(text, end + 1)) {
        ++at.column;
        continue;
      }
      const std::string key = decoded(quoted);
      const auto [it, inserted] = scopes.back().keys.emplace(key, start.line);
      if (!inserted) {
        throw ParseError(
            "duplicate key '" + key + "' (first given on line " + std::to_string(it->second) + ")",
            file_name, start.line, start.column);
      }
    } else if (c == '{' || c == '[') {
      scopes.push_back(Scope{c == '{', {}});
    } else if ((c == '}' || c == ']') && !scopes.empty()) {
      scopes.pop_back();
    }
    if (c == '\n') {
      ++at.line;
      at.column = 1;
    } else {
      ++at.column;
    }
  }
}

}  // namespace fspm
