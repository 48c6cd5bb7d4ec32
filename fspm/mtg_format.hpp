#pragma once
// Export to OpenAlea's MTG text format (Godin and Caraglio 1998; the FORM-A coding used by
// openalea.mtg): one plant `P1` at scale 1 decomposed into internodes `I`, leaves `L`, flowers `F`
// and buds `B` at scale 2, with `<` for the successor on the same axis and `+` for branches.
// Features: XX YY ZZ (node end), Length, Radius, BirthTime, Order, and every user attribute.
#include <iosfwd>

#include "fspm/tree_graph.hpp"

namespace fspm {

void write_mtg(const TreeGraph& tree, std::ostream& out);

}  // namespace fspm
