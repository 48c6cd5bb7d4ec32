#include "fspm/number_column.hpp"

#include <cctype>
#include <cmath>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/number_text.hpp"

namespace fspm {
namespace {

struct Field {
  std::string_view text;
  int column;  // 1-based character position of the field's first character
};

std::string_view trim(std::string_view s, int& offset) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) {
    s.remove_prefix(1);
    ++offset;
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

std::vector<Field> split_csv(std::string_view line) {
  std::vector<Field> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
    int col = static_cast<int>(start) + 1;
    std::string_view f = trim(line.substr(start, end - start), col);
    if (f.size() >= 2 && f.front() == '"' && f.back() == '"') {
      f = f.substr(1, f.size() - 2);
      ++col;
    }
    fields.push_back({f, col});
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

double parse_field(const Field& f, const std::string& path, int line) {
  const auto v = parse_number(f.text);
  if (!v || !std::isfinite(*v)) {
    throw ParseError("expected a finite number, found '" + std::string(f.text) + "'", path, line,
                     f.column);
  }
  return *v;
}

}  // namespace

std::vector<double> read_number_column(const std::string& path, std::string_view column) {
  return parse_number_column(read_text_input_file(path), path, column);
}

std::vector<double> parse_number_column(std::string_view content_text, const std::string& path,
                                        std::string_view column) {
  std::istringstream in{std::string(content_text)};
  std::vector<double> values;
  std::string text;
  int line = 0;
  long index = -1;  // column index once the header is read
  bool header_skipped = false;
  while (std::getline(in, text)) {
    ++line;
    int offset = 1;
    const std::string_view content = trim(text, offset);
    if (content.empty() || content.front() == '#') continue;
    if (column.empty()) {
      if (content.find(',') != std::string_view::npos) {
        throw ParseError(
            "expected one number per line, found several fields; use --column "
            "NAME to pick a column of a CSV file",
            path, line, offset);
      }
      // A one-column CSV file: its first line, a name rather than a number, is the header.
      // ("inf" and "nan" are numbers, refused below, not names.)
      if (values.empty() && !header_skipped && !parse_number(content) &&
          (std::isalpha(static_cast<unsigned char>(content.front())) != 0 ||
           content.front() == '"')) {
        header_skipped = true;
        continue;
      }
      values.push_back(parse_field({content, offset}, path, line));
      continue;
    }
    const auto fields = split_csv(text);
    if (index < 0) {
      std::string names;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        if (fields[k].text == column) index = static_cast<long>(k);
        names += (k ? ", " : "") + std::string(fields[k].text);
      }
      if (index < 0) {
        throw ValueError("no column '" + std::string(column) + "' in the header (" + names + ")",
                         path, line);
      }
      continue;
    }
    if (static_cast<std::size_t>(index) >= fields.size()) {
      throw ParseError("row has " + std::to_string(fields.size()) + " fields, expected column '" +
                           std::string(column) + "' (field " + std::to_string(index + 1) + ")",
                       path, line);
    }
    values.push_back(parse_field(fields[static_cast<std::size_t>(index)], path, line));
  }
  if (values.empty()) {
    throw ParseError(line == 0 ? "the file is empty: expected numbers, one per line"
                               : "expected numbers, found none",
                     path, line == 0 ? 1 : line);
  }
  return values;
}

}  // namespace fspm
