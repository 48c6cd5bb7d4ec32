#include "lsystem/source_text.hpp"

#include <algorithm>
#include <cctype>

#include "fspm/error.hpp"

namespace fspm::lsystem {

void SourceText::append(std::string_view text, const std::string& file, int line, int column) {
  if (segments_.empty() || segments_.back().file != file || segments_.back().line != line ||
      text_.size() - segments_.back().offset + static_cast<std::size_t>(segments_.back().column) !=
          static_cast<std::size_t>(column)) {
    segments_.push_back({text_.size(), file, line, column});
  }
  text_.append(text);
}

SourcePosition SourceText::position(std::size_t offset) const {
  if (segments_.empty()) return {"", 0, 0};
  auto it = std::upper_bound(segments_.begin(), segments_.end(), offset,
                             [](std::size_t o, const Segment& s) { return o < s.offset; });
  if (it != segments_.begin()) --it;
  return {it->file, it->line, it->column + static_cast<int>(offset - it->offset)};
}

void Cursor::skip_space() {
  while (pos_ < end_ && std::isspace(static_cast<unsigned char>(source_->text()[pos_]))) ++pos_;
}

bool Cursor::accept(std::string_view token) {
  skip_space();
  if (source_->text().compare(pos_, token.size(), token) == 0 && pos_ + token.size() <= end_) {
    pos_ += token.size();
    return true;
  }
  return false;
}

void Cursor::expect(char c, std::string_view what) {
  skip_space();
  if (peek() != c) fail(what);
  ++pos_;
}

std::string_view Cursor::rest() const {
  return std::string_view(source_->text()).substr(pos_, end_ > pos_ ? end_ - pos_ : 0);
}

void Cursor::fail(std::string_view expected) const {
  std::string found = at_end() ? std::string("end of line") : "'" + std::string(1, peek()) + "'";
  fail_at(pos_, "expected " + std::string(expected) + ", found " + found);
}

void Cursor::fail_at(std::size_t pos, std::string_view message) const {
  const SourcePosition p = source_->position(pos);
  throw ParseError(std::string(message), p.file, p.line, p.column);
}

}  // namespace fspm::lsystem
