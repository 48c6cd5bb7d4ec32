#pragma once
// Newick trees: topology, one label per node (internal labels after the closing parenthesis, e.g.
// `(100,(200,300)1)1000;` or `((A:1,B:2)C:0.5,D:1);`) and optional branch lengths (`:0.5`).
// Unquoted numeric labels become the attribute "label", branch lengths the attribute
// "branch_length" (NaN where a node has none). Any other label is a name: a taxon name such as
// `Quercus_robur` ('_' reads as a blank) or a quoted label `'Quercus robur'` (quoted labels are
// always names; '' inside quotes is one quote). Comments in square brackets are skipped.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm {

inline constexpr std::string_view kNewickLabel = "label";
inline constexpr std::string_view kNewickBranchLength = "branch_length";

// A tree with the names of its nodes: names[n] is node n's name, empty where it has none (or a
// numeric label). Tree attributes are numbers, so names travel beside the tree.
struct NamedTree {
  TreeGraph tree;
  std::vector<std::string> names;
};

// Parses one tree ending in ';'. Throws ParseError with `source`, line and column.
NamedTree parse_newick_named(std::string_view text, const std::string& source = "<newick>");
// The same, dropping the names (topology, "label" and "branch_length" only).
TreeGraph parse_newick(std::string_view text, const std::string& source = "<newick>");
// Writes `label_attribute` (when the tree has it and the value is not NaN) as each node's label
// and "branch_length" when present; ends with ";".
std::string to_newick(const TreeGraph& tree, std::string_view label_attribute = kNewickLabel);
// The same with names (one per node, or none): a node's name, quoted where needed, takes the place
// of its number. Throws ValueError when `names` is neither empty nor one per node.
std::string to_newick_named(const TreeGraph& tree, std::span<const std::string> names,
                            std::string_view label_attribute = kNewickLabel);

}  // namespace fspm
