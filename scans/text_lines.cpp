#include "scans/text_lines.hpp"

#include <cmath>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm::scans {

bool TextLines::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;  // offset() never passes the end of the text
  ++line_;
  return true;
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != ',') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

double parse_coordinate(std::string_view text, const std::string& file, int line) {
  const std::optional<double> value = parse_number(text);
  if (!value || !std::isfinite(*value)) {
    throw ParseError("expected a finite number, got '" + std::string(text) + "'", file, line);
  }
  return *value;
}

}  // namespace fspm::scans
