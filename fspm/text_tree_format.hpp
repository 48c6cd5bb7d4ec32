#pragma once
// The `.tree` text format: versioned, line-oriented, diff-friendly and streamable (parents
// precede children, one node per line). Specified in docs/formats.md. Numbers are written in
// the shortest form that reads back to the identical double, so a round trip is bit-exact.
#include <iosfwd>
#include <string>
#include <string_view>

#include "fspm/tree_graph.hpp"

namespace fspm {

inline constexpr int kTextTreeFormatVersion = 1;

// `comment` (where the tree came from: the file, its units) is written as a '#' line after the
// magic line; readers skip it.
void write_tree_text(const TreeGraph& tree, std::ostream& out, std::string_view comment = {});
// `source` names the input in error messages (a file path or "<stdin>").
TreeGraph read_tree_text(std::istream& in, const std::string& source);

}  // namespace fspm
