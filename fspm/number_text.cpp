#include "fspm/number_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace fspm {
namespace {

// Below this a printed number is rounding noise; see format_significant.
constexpr double kNoiseBelow = 1e-12;

// "5.1900" -> "5.19", "12.000" -> "12", "1.200e-05" -> "1.2e-05".
void strip_trailing_zeros(std::string& text) {
  const std::size_t exponent = text.find('e');
  std::string tail = exponent == std::string::npos ? "" : text.substr(exponent);
  std::string head = text.substr(0, exponent);
  if (head.find('.') != std::string::npos) {
    while (head.back() == '0') head.pop_back();
    if (head.back() == '.') head.pop_back();
  }
  text = head + tail;
}

}  // namespace

void append_number(std::string& out, double value) {
  if (std::isnan(value)) {
    out += "nan";
    return;
  }
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof(buf), value);
  out.append(buf, res.ptr);
}

std::string format_significant(double value, int digits) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  digits = std::clamp(digits, 1, 17);
  const double magnitude = std::abs(value);
  if (magnitude < kNoiseBelow) return "0";
  char buf[64];
  std::to_chars_result res{};
  if (magnitude >= 1e15) {
    res = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::scientific, digits - 1);
  } else if (magnitude < 1e-4) {
    res = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::scientific, digits - 1);
  } else {
    // Decimals after the point so that `digits` significant digits remain (none for large values).
    const int exponent = static_cast<int>(std::floor(std::log10(magnitude)));
    const int decimals = std::max(0, digits - 1 - exponent);
    res = std::to_chars(buf, buf + sizeof(buf), value, std::chars_format::fixed, decimals);
  }
  std::string text(buf, res.ptr);
  strip_trailing_zeros(text);
  if (text == "-0") text = "0";
  return text;
}

std::optional<double> parse_number(std::string_view text) {
  if (text.empty()) return std::nullopt;
  // from_chars does not take a leading '+'; accept it as people write it.
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), value);
  if (res.ec != std::errc() || res.ptr != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace fspm
