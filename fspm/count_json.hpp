#pragma once
// A count as --json writes it: its number, or the text "more than 10^19" where it saturated at
// 2^64 - 1 (fspm/saturating.hpp), so no reader takes 18446744073709551615 for a count.
#include <cstdint>
#include <nlohmann/json.hpp>

#include "fspm/saturating.hpp"

namespace fspm {

inline nlohmann::json count_json(std::uint64_t count) {
  if (count == kSaturated) return count_text(count);
  return count;
}

}  // namespace fspm
