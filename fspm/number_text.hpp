#pragma once
// Exact text form of doubles: shortest digits that read back to the identical value.
#include <optional>
#include <string>
#include <string_view>

namespace fspm {

// Appends the shortest round-trip representation ("nan", "inf", "-inf" for non-finite values).
void append_number(std::string& out, double value);
// Parses the whole of `text` as a double (also "nan", "inf", "-inf"); nullopt when it is not one.
std::optional<double> parse_number(std::string_view text);

}  // namespace fspm
