#include "environment/radiation_file.hpp"

#include <charconv>
#include <cmath>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/trim.hpp"

namespace fspm::environment {
namespace {

double number(std::string_view f, const char* what, const std::string& file, int line) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
  if (f.empty() || ec != std::errc() || end != f.data() + f.size() || !std::isfinite(v)) {
    throw ParseError(std::string("expected ") + what + ", got \"" + std::string(f) + "\"", file,
                     line);
  }
  return v;
}

}  // namespace

std::vector<double> parse_hourly_global_csv(std::string_view text, const std::string& file_name) {
  std::vector<double> global(24, 0.0);
  std::vector<bool> seen(24, false);
  bool header = false;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::string_view line =
        trim(text.substr(pos, nl == std::string_view::npos ? nl : nl - pos));
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line_no;
    if (line.empty() || line.front() == '#') continue;
    const std::size_t comma = line.find(',');
    const std::string_view a = trim(line.substr(0, comma));
    const std::string_view b =
        comma == std::string_view::npos ? std::string_view{} : trim(line.substr(comma + 1));
    if (!header) {
      if (a != "hour" || b != "global_W_m2") {
        throw ParseError("expected the header hour,global_W_m2, got \"" + std::string(line) + "\"",
                         file_name, line_no);
      }
      header = true;
      continue;
    }
    const double hour = number(a, "an hour 0-23", file_name, line_no);
    if (hour != std::floor(hour) || hour < 0 || hour > 23) {
      throw ParseError("expected an hour 0-23, got \"" + std::string(a) + "\"", file_name, line_no);
    }
    const double w = number(b, "a global radiation >= 0 W m-2", file_name, line_no);
    if (w < 0.0) {
      throw ParseError("expected a global radiation >= 0 W m-2, got \"" + std::string(b) + "\"",
                       file_name, line_no);
    }
    const int h = static_cast<int>(hour);
    if (seen[h]) {
      throw ParseError("hour " + std::to_string(h) + " is given twice", file_name, line_no);
    }
    seen[h] = true;
    global[h] = w;
  }
  if (!header)
    throw ParseError("expected the header hour,global_W_m2 (file is empty)", file_name, 1);
  return global;
}

std::vector<double> read_hourly_global_csv(const std::string& path) {
  return parse_hourly_global_csv(read_text_input_file(path), path);
}

}  // namespace fspm::environment
