#pragma once
// Text after preprocessing, with a map back to the original file, line and column, and a cursor
// that reports errors as `file:line:column: expected ...`.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fspm::lsystem {

struct SourcePosition {
  std::string file;
  int line = 0;
  int column = 0;
};

class SourceText {
 public:
  SourceText() = default;
  // Appends `text` whose first character is at `file:line:column`.
  void append(std::string_view text, const std::string& file, int line, int column = 1);
  const std::string& text() const { return text_; }
  SourcePosition position(std::size_t offset) const;

 private:
  struct Segment {
    std::size_t offset;
    std::string file;
    int line;
    int column;
  };
  std::string text_;
  std::vector<Segment> segments_;
};

class Cursor {
 public:
  Cursor(const SourceText& source, std::size_t begin, std::size_t end)
      : source_(&source), pos_(begin), end_(end) {}
  std::size_t pos() const { return pos_; }
  void set_pos(std::size_t pos) { pos_ = pos; }
  std::size_t end() const { return end_; }
  bool at_end() const { return pos_ >= end_; }
  char peek(std::size_t ahead = 0) const {
    return pos_ + ahead < end_ ? source_->text()[pos_ + ahead] : '\0';
  }
  void advance(std::size_t n = 1) { pos_ += n; }
  void skip_space();
  // Skips spaces, then consumes `token` if it is next.
  bool accept(std::string_view token);
  // Skips spaces, then requires `c`; otherwise throws a ParseError naming `what`.
  void expect(char c, std::string_view what);
  SourcePosition position() const { return source_->position(pos_); }
  std::string_view rest() const;
  [[noreturn]] void fail(std::string_view expected) const;
  [[noreturn]] void fail_at(std::size_t pos, std::string_view message) const;

 private:
  const SourceText* source_;
  std::size_t pos_;
  std::size_t end_;
};

}  // namespace fspm::lsystem
