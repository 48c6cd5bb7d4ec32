#include "fspm/closest_name.hpp"

#include <algorithm>
#include <cctype>

namespace fspm {
namespace {

bool same_letter(char x, char y) {
  return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
}

// Insertions, deletions, substitutions and swaps of neighbours ("LNE" for "LEN") cost 1.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t w = b.size() + 1;
  std::vector<std::size_t> d((a.size() + 1) * w);
  for (std::size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = same_letter(a[i - 1], b[j - 1]) ? 0 : 1;
      std::size_t best =
          std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + cost});
      if (i > 1 && j > 1 && same_letter(a[i - 1], b[j - 2]) && same_letter(a[i - 2], b[j - 1])) {
        best = std::min(best, d[(i - 2) * w + j - 2] + 1);
      }
      d[i * w + j] = best;
    }
  }
  return d[a.size() * w + b.size()];
}

}  // namespace

std::string closest_name(std::string_view name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t best_distance = 0;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(name, k);
    if (best.empty() || d < best_distance) {
      best = k;
      best_distance = d;
    }
  }
  if (best.empty() || 2 * best_distance > std::max(name.size(), best.size())) return {};
  return best;
}

std::string closest_name_hint(std::string_view name, const std::vector<std::string>& known) {
  if (known.empty()) return {};
  const std::string best = closest_name(name, known);
  if (!best.empty()) return " (did you mean '" + best + "'?)";
  std::string list;
  for (std::size_t i = 0; i < known.size() && i < 8; ++i) list += (i ? ", " : "") + known[i];
  if (known.size() > 8) list += ", ...";
  return " (known: " + list + ")";
}

std::string unknown_key_message(std::string_view qualified_key, std::string_view key,
                                const std::vector<std::string>& known) {
  return "unknown key '" + std::string(qualified_key) + "'" + closest_name_hint(key, known);
}

}  // namespace fspm
