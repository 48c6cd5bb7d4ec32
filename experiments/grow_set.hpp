#pragma once
// The sets of the grow model's `set` parameter (Pirk 4.5.4): the open-grown trees O, the trees
// grown beside the scene's obstacles G, and the open-grown trees adapted to the obstacles T.
#include <optional>
#include <string_view>

namespace fspm::experiments {

enum class GrowSet { kOpen, kBesideObstacles, kAdapted };

inline constexpr GrowSet kGrowSets[] = {GrowSet::kOpen, GrowSet::kBesideObstacles,
                                        GrowSet::kAdapted};

// "O", "G", "T": the values `set` takes.
constexpr std::string_view grow_set_name(GrowSet set) {
  switch (set) {
    case GrowSet::kOpen:
      return "O";
    case GrowSet::kBesideObstacles:
      return "G";
    case GrowSet::kAdapted:
      return "T";
  }
  return "G";
}

// Inverse of grow_set_name; nothing for another text.
constexpr std::optional<GrowSet> find_grow_set(std::string_view name) {
  for (GrowSet s : kGrowSets) {
    if (grow_set_name(s) == name) return s;
  }
  return std::nullopt;
}

// What the set means, one sentence without its full stop.
constexpr std::string_view grow_set_meaning(GrowSet set) {
  switch (set) {
    case GrowSet::kOpen:
      return "grown in the open, without the scene's obstacles (its sky and ground only)";
    case GrowSet::kBesideObstacles:
      return "grown in the scene, beside its obstacles, from the start";
    case GrowSet::kAdapted:
      return "grown like O, then adapted to the scene's obstacles by plastic adaptation "
             "(Pirk 2013, 4.3-4.4): branches pruned and bent instead of regrown";
  }
  return {};
}

}  // namespace fspm::experiments
