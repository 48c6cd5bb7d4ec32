#pragma once
// Reading one list of numbers from a text file, as `fspm stats` takes its samples: either one
// number per line (a first line that is a name, not a number, is the header of a one-column CSV
// file and skipped), or one column of a CSV file chosen by its header name. Blank lines and lines
// starting with '#' are skipped.
#include <string>
#include <string_view>
#include <vector>

namespace fspm {

// Throws IoError when the file cannot be read, ParseError (file, line, column) for a field that
// is not a finite number, a row without the column, a missing or empty file, and ValueError when
// the header has no column of that name.
std::vector<double> read_number_column(const std::string& path, std::string_view column = {});
// The same for text already in memory; `path` names it in messages.
std::vector<double> parse_number_column(std::string_view text, const std::string& path,
                                        std::string_view column = {});

}  // namespace fspm
