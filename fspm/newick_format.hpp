#pragma once
// Newick trees: topology plus one numeric label per node (internal labels after the closing
// parenthesis, e.g. `(100,(200,300)1)1000;`) and optional branch lengths (`:0.5`).
// Labels become the attribute "label", branch lengths the attribute "branch_length"
// (NaN where a node has none).
#include <string>
#include <string_view>

#include "fspm/tree_graph.hpp"

namespace fspm {

inline constexpr std::string_view kNewickLabel = "label";
inline constexpr std::string_view kNewickBranchLength = "branch_length";

// Parses one tree ending in ';'. Throws ParseError with `source`, line and column.
TreeGraph parse_newick(std::string_view text, const std::string& source = "<newick>");
// Writes `label_attribute` (when the tree has it and the value is not NaN) as each node's label
// and "branch_length" when present; ends with ";".
std::string to_newick(const TreeGraph& tree, std::string_view label_attribute = kNewickLabel);

}  // namespace fspm
