#pragma once
// Reading and writing tree graphs in every supported format, chosen by extension or by name:
//   .tree  text format (versioned, line-oriented)     .treeb binary format
//   .nwk   Newick (topology + one numeric label)      .mtg   OpenAlea MTG (write only)
// Writes go to a temporary file in the same directory, renamed over the target on success, so
// a failed write never leaves a half-written file.
#include <string>
#include <string_view>

#include "fspm/tree_graph.hpp"

namespace fspm {

enum class TreeFormat { kText, kBinary, kNewick, kMtg };

// Format from a name ("tree", "treeb", "nwk"/"newick", "mtg") or, when `name` is empty, from the
// extension of `path`. Throws ValueError naming what was expected.
TreeFormat tree_format_for(const std::string& path, std::string_view name = {});
std::string_view tree_format_name(TreeFormat format);

TreeGraph read_tree_file(const std::string& path, std::string_view format = {});
void write_tree_file(const TreeGraph& tree, const std::string& path, std::string_view format = {});

}  // namespace fspm
