#pragma once
// OpenAlea's MTG text format (Godin and Caraglio 1998; the FORM-A coding used by openalea.mtg).
//
// Export: one plant `P1` at scale 1 decomposed into internodes `I`, leaves `L`, flowers `F` and
// buds `B` at scale 2, with `<` for the successor on the same axis and `+` for branches.
// Features: XX YY ZZ (node end), Length, Radius, BirthTime, Order, and every user attribute.
//
// Import: the entities of the finest scale become the tree's nodes, whatever the coarser scales
// (plants, growth units, axes) that decompose them; `<` and `+` give the topology, `^` refers to
// the last entity of the same column and `/` to a component's complex. Symbols L, F and B are
// leaves, flowers and buds, every other symbol an internode. Geometry from the features XX YY ZZ
// (the entity's top), Length, Radius (or Diameter, TopDia: halved), BirthTime and Order; an
// entity without coordinates is drawn by a turtle (continuing its predecessor, branches at 45
// degrees, turned 137.5 degrees per node along the axis) with its Length or 1. Other numeric
// features become attributes, and so do the label numbers: "index" (the node's own) and "<S>_index"
// per coarser symbol S (U_index: the growth unit an internode belongs to). One tree per file: a
// second finest-scale root is an error; plants without components give an empty tree.
#include <iosfwd>
#include <string>
#include <string_view>

#include "fspm/tree_graph.hpp"

namespace fspm {

void write_mtg(const TreeGraph& tree, std::ostream& out);

// Throws ParseError naming `file`, the line and what was expected.
TreeGraph parse_mtg(std::string_view text, const std::string& file = "<mtg>");

}  // namespace fspm
