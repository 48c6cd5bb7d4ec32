#pragma once
// Line-by-line reading of small text formats (XYZ, CSV, PCD, OBJ, ASCII PLY) with the line number
// kept for error messages, and splitting a line into whitespace- or comma-separated fields.
#include <string>
#include <string_view>
#include <vector>

namespace fspm::scans {

class TextLines {
 public:
  TextLines(std::string_view text, std::size_t start = 0) : text_(text), pos_(start) {}
  // Next line without its end-of-line characters; false at the end of the text.
  bool next(std::string_view& line);
  int line_number() const { return line_; }
  // Byte offset of the next unread character (where binary data starts after a text header).
  std::size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  std::size_t pos_;
  int line_ = 0;
};

// Fields separated by spaces, tabs or commas; empty fields between two commas are kept out.
std::vector<std::string_view> split_fields(std::string_view line);

// Parses field `text` as a finite double; throws ParseError naming file, line and the field.
double parse_coordinate(std::string_view text, const std::string& file, int line);

}  // namespace fspm::scans
