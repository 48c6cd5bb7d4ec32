#pragma once
// Text forms of doubles. Exact (append_number, for files: JSON, CSV, .tree) gives the shortest
// digits that read back to the identical value; for people (format_significant, every printed
// table and summary) a few significant digits.
#include <optional>
#include <string>
#include <string_view>

namespace fspm {

// Appends the shortest round-trip representation ("nan", "inf", "-inf" for non-finite values).
void append_number(std::string& out, double value);
// A number for people: `digits` significant digits (1 to 17), without trailing zeros and
// without an exponent between 1e-4 and 1e15 ("5.19", "0.0123", "452.6", "1.235e-05").
// Integer parts are never cut: a value of 10^digits or more prints as its rounded integer
// ("6059", "12346"), so counts read as counts. Magnitudes below 1e-12 print as "0": in every
// quantity fspm prints (metres, light fractions, unit vectors, distances, p values) they are
// floating-point rounding noise (a sum of terms that cancel), not a measurement. "nan", "inf",
// "-inf" for non-finite values.
std::string format_significant(double value, int digits = 4);
// Parses the whole of `text` as a double (also "nan", "inf", "-inf"); nullopt when it is not one.
std::optional<double> parse_number(std::string_view text);

}  // namespace fspm
