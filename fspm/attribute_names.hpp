#pragma once
// Names of the per-node tree attributes that more than one module writes or reads. A model may
// add attributes of its own; these are the ones others rely on (docs/formats.md lists them all).
namespace fspm {

// 1 for an organ that died (GreenLab self-pruning with a pruning period), else 0.
inline constexpr const char* kDeadAttribute = "dead";
// 1 for a node removed by plastic adaptation but kept flagged (fspm adapt --keep-pruned).
inline constexpr const char* kPrunedAttribute = "pruned";
// Light a leaf cluster or bud receives, as a fraction of the unobstructed sky (Pirk eq. 4.3).
inline constexpr const char* kLightAttribute = "light";
// One-sided leaf area of a node's leaves, m^2.
inline constexpr const char* kLeafAreaAttribute = "leaf_area";

}  // namespace fspm
