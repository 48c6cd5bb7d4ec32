#pragma once
// The `.treeb` binary format: a small header and then each column as one little-endian array,
// so reading and writing run at memory speed. Specified in docs/formats.md.
#include <iosfwd>
#include <string>

#include "fspm/tree_graph.hpp"

namespace fspm {

inline constexpr int kBinaryTreeFormatVersion = 1;

void write_tree_binary(const TreeGraph& tree, std::ostream& out);
TreeGraph read_tree_binary(std::istream& in, const std::string& source);

}  // namespace fspm
