#pragma once
// Reading and writing tree graphs in every supported format, chosen by extension or by name:
//   .tree  text format (versioned, line-oriented)     .treeb binary format
//   .nwk   Newick (topology, labels or names)         .mtg   OpenAlea MTG
// Writes go to a temporary file in the same directory, renamed over the target on success, so
// a failed write never leaves a half-written file.
#include <string>
#include <string_view>

#include "fspm/mtg_tree.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

enum class TreeFormat { kText, kBinary, kNewick, kMtg };

// Format from a name ("tree", "treeb", "nwk"/"newick", "mtg") or, when `name` is empty, from the
// extension of `path`. Throws ValueError naming what was expected.
TreeFormat tree_format_for(const std::string& path, std::string_view name = {});
std::string_view tree_format_name(TreeFormat format);

TreeGraph read_tree_file(const std::string& path, std::string_view format = {});
// read_tree_file with the options of an MTG file (its units, scale, plant) rather than the
// process's defaults (set_default_mtg_tree_options).
TreeGraph read_tree_file(const std::string& path, std::string_view format,
                         const MtgTreeOptions& mtg);
void write_tree_file(const TreeGraph& tree, const std::string& path, std::string_view format = {});

// Whether the format carries node names (taxon names, quoted labels): Newick only.
bool tree_format_keeps_names(TreeFormat format);
// The tree and its node names: from Newick, as parse_newick_named gives them; from the other
// formats, which carry no names, an empty `names`.
NamedTree read_named_tree_file(const std::string& path, std::string_view format = {});
// Writes the names where the format carries them (Newick) and drops them otherwise; `comment`
// (the tree's source and units) goes into formats that keep comments (.tree).
void write_named_tree_file(const NamedTree& named, const std::string& path,
                           std::string_view format = {}, std::string_view comment = {});

}  // namespace fspm
