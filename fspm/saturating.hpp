#pragma once
// Counts that stop at 2^64 - 1 instead of wrapping: module counts of derivations far too large
// to carry out (ABOP Fig. 1.24a at n = 40 has about 10^28 modules).
#include <cstdint>
#include <limits>
#include <string>

namespace fspm {

inline constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

constexpr std::uint64_t add_saturating(std::uint64_t a, std::uint64_t b) {
  return a > kSaturated - b ? kSaturated : a + b;
}

constexpr std::uint64_t multiply_saturating(std::uint64_t a, std::uint64_t b) {
  if (a == 0 || b == 0) return 0;
  return a > kSaturated / b ? kSaturated : a * b;
}

// A count as people read it: its digits, or "more than 10^19" where it saturated (2^64 - 1 is
// about 1.8 x 10^19), never the 18446744073709551615 of the saturation itself.
inline std::string count_text(std::uint64_t n) {
  return n == kSaturated ? "more than 10^19" : std::to_string(n);
}

}  // namespace fspm
