#include "fspm/closest_name.hpp"

#include <algorithm>
#include <cctype>
#include <numeric>

namespace fspm {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      const std::size_t next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
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

}  // namespace fspm
