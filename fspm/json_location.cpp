#include "fspm/json_location.hpp"

#include <vector>

namespace fspm {
namespace {

// Walks a valid JSON text without building it, following the pointer's tokens.
class Walker {
 public:
  explicit Walker(std::string_view text) : text_(text) {}

  // Offset of the deepest place along `tokens` that exists (the key of a last object token).
  std::size_t find(const std::vector<std::string>& tokens) {
    std::size_t found = 0;
    skip_space();
    for (std::size_t i = 0; i < tokens.size() && pos_ < text_.size(); ++i) {
      const bool last = i + 1 == tokens.size();
      if (text_[pos_] == '{') {
        if (!enter_member(tokens[i])) return found;
        if (last) return key_;
        skip_space();
        ++pos_;  // ':'
        skip_space();
      } else if (text_[pos_] == '[') {
        if (!enter_element(tokens[i])) return found;
      } else {
        return found;
      }
      found = pos_;
    }
    return found;
  }

 private:
  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\n' ||
                                   text_[pos_] == '\t' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }
  // A string starting at pos_ ('"'), returned with escapes kept as written.
  std::string_view string() {
    const std::size_t start = ++pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') pos_ += text_[pos_] == '\\' ? 2 : 1;
    return text_.substr(start, (pos_++) - start);
  }
  void skip_value() {
    if (text_[pos_] == '"') {
      string();
      return;
    }
    int depth = 0;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '"') {
        string();
        continue;
      }
      if (c == '{' || c == '[') ++depth;
      if (c == '}' || c == ']') {
        if (depth == 0) return;
        if (--depth == 0) {
          ++pos_;
          return;
        }
      }
      if (depth == 0 && c == ',') return;
      ++pos_;
    }
  }
  // From '{': to the key `name` (key_ its offset, pos_ after it); false when absent.
  bool enter_member(const std::string& name) {
    ++pos_;
    for (skip_space(); pos_ < text_.size() && text_[pos_] == '"'; skip_space()) {
      key_ = pos_;
      if (string() == name) return true;
      skip_space();
      ++pos_;  // ':'
      skip_space();
      skip_value();
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') ++pos_;
    }
    return false;
  }
  // From '[': to the start of element `index`; false when absent.
  bool enter_element(const std::string& index) {
    if (index.empty() || index.size() > 18 ||
        index.find_first_not_of("0123456789") != std::string::npos) {
      return false;
    }
    const std::size_t wanted = std::stoul(index);
    ++pos_;
    skip_space();
    for (std::size_t i = 0; pos_ < text_.size() && text_[pos_] != ']'; ++i) {
      if (i == wanted) return true;
      skip_value();
      skip_space();
      if (pos_ < text_.size() && text_[pos_] == ',') ++pos_;
      skip_space();
    }
    return false;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t key_ = 0;
};

std::vector<std::string> pointer_tokens(std::string_view pointer) {
  std::vector<std::string> tokens;
  std::size_t start = 0;
  while (start < pointer.size()) {
    if (pointer[start] == '/') ++start;
    const std::size_t end = std::min(pointer.find('/', start), pointer.size());
    tokens.emplace_back(pointer.substr(start, end - start));
    start = end;
  }
  return tokens;
}

}  // namespace

TextPosition json_pointer_position(std::string_view text, std::string_view pointer) {
  if (pointer.size() > 10000) return {};  // error paths are short; a guard against runaway ones
  const std::size_t offset = Walker(text).find(pointer_tokens(pointer));
  TextPosition p{1, 1};
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

}  // namespace fspm
