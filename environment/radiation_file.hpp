#pragma once
// Measured hourly global radiation for a real sky (daylight.hpp): a CSV with the header
// hour,global_W_m2, one row per local clock hour (0-23, the hour's mean irradiance on a horizontal
// plane in W m-2); blank lines and '#' comments are skipped. Hours without a row have none.
#include <string>
#include <string_view>
#include <vector>

namespace fspm::environment {

// Global radiation per hour 0..23 (index = hour; absent hours 0). Throws ParseError naming the
// file, line and what was expected (bad header, an hour outside 0-23 or given twice, a negative
// or non-finite value).
std::vector<double> parse_hourly_global_csv(std::string_view text,
                                            const std::string& file_name = "<radiation>");
std::vector<double> read_hourly_global_csv(const std::string& path);

}  // namespace fspm::environment
