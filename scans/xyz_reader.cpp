#include "scans/xyz_reader.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/number_text.hpp"
#include "scans/text_lines.hpp"

namespace fspm::scans {
namespace {

bool is_comment(std::string_view line) {
  const std::size_t i = line.find_first_not_of(" \t");
  if (i == std::string_view::npos) return true;
  return line[i] == '#' || line.substr(i, 2) == "//";
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

// Columns of x, y, z from a CSV header; the first three when it does not name them.
std::array<std::size_t, 3> header_columns(const std::vector<std::string_view>& fields) {
  std::array<std::size_t, 3> col{0, 1, 2};
  std::array<bool, 3> found{false, false, false};
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const std::string n = lower(fields[i]);
    for (int c = 0; c < 3; ++c) {
      if (!found[c] && n == std::string(1, static_cast<char>('x' + c))) {
        col[c] = i;
        found[c] = true;
      }
    }
  }
  return col;
}

// A header names columns: every field starts with a letter, '_' or a quote. A first line that
// does not (a point whose separators a reader cannot see, such as Latin-1's no-break space) is
// read as data, so a bad separator is an error naming the line rather than a lost first point.
bool is_header(const std::vector<std::string_view>& fields) {
  if (fields.empty() || parse_number(fields[0])) return false;
  return std::all_of(fields.begin(), fields.end(), [](std::string_view f) {
    const auto c = static_cast<unsigned char>(f[0]);
    return std::isalpha(c) || c == '_' || c == '"' || c == '\'';
  });
}

// The text without a UTF-8 byte-order mark (which spreadsheet programs write); UTF-16 text,
// whose every other byte is NUL, is refused as such.
std::string_view without_byte_order_mark(std::string_view text, const std::string& path) {
  if (text.starts_with("\xEF\xBB\xBF")) return text.substr(3);
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF")) {
    throw ParseError("UTF-16 text (a byte-order mark FF FE or FE FF), expected ASCII or UTF-8",
                     path, 1);
  }
  return text;
}

}  // namespace

PointSet parse_xyz_points(std::string_view text, const std::string& path) {
  TextLines lines(without_byte_order_mark(text, path));
  std::string_view line;
  std::array<std::size_t, 3> col{0, 1, 2};
  bool first = true;
  PointSet out;
  while (lines.next(line)) {
    if (is_comment(line)) continue;
    const std::vector<std::string_view> f = split_fields(line);
    if (first && is_header(f)) {
      col = header_columns(f);
      first = false;
      continue;
    }
    first = false;
    const std::size_t need = std::max({col[0], col[1], col[2]}) + 1;
    if (f.size() < need) {
      throw ParseError("expected at least " + std::to_string(need) + " values (x y z), got " +
                           std::to_string(f.size()),
                       path, lines.line_number());
    }
    out.points.emplace_back(parse_coordinate(f[col[0]], path, lines.line_number()),
                            parse_coordinate(f[col[1]], path, lines.line_number()),
                            parse_coordinate(f[col[2]], path, lines.line_number()));
  }
  return out;
}

PointSet read_xyz_points(const std::string& path) {
  return parse_xyz_points(read_input_file(path), path);
}

}  // namespace fspm::scans
