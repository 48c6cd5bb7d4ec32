#pragma once
// OpenAlea's MTG text format (Godin and Caraglio 1998; the FORM-A coding used by openalea.mtg).
//
// Export: one plant `P1` at scale 1 decomposed into internodes `I`, leaves `L`, flowers `F` and
// buds `B` at scale 2, with `<` for the successor on the same axis and `+` for branches.
// Features: XX YY ZZ (node end), Length, Radius, BirthTime, Order, Organ (leaf, flower, bud;
// empty for an internode), and every user attribute except those an import derives from the
// MTG itself (class, index, inferred, <S>_index).
//
// Import (parse_mtg): read_mtg (fspm/mtg_reader.hpp) then mtg_to_tree (fspm/mtg_tree.hpp) with
// the default options (set_default_mtg_tree_options): one scale of the multiscale graph, its
// geometry measured or inferred, its features as attributes. docs/formats.md has the details.
#include <iosfwd>
#include <string>
#include <string_view>

#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

void write_mtg(const TreeGraph& tree, std::ostream& out, const std::string& path = {},
               std::uint64_t max_code_bytes = kMaxMtgCodeBytes);

// Throws ParseError naming `file`, the line and what was expected.
TreeGraph parse_mtg(std::string_view text, const std::string& file = "<mtg>");
TreeGraph parse_mtg(std::string_view text, const std::string& file, const MtgTreeOptions& options);

}  // namespace fspm
