#pragma once
// Writing a multiscale tree graph as an MTG coding file that read_mtg (and OpenAlea's reader)
// reads back to the same graph: the header (CODE, CLASSES, DESCRIPTION, FEATURES), then one line
// per entity with its features. An axis stays in one column ('^<' continues it, '^/' descends
// into the first component of the entity above); a branch ('+') opens the next column to the
// right; dated repetitions follow their entity as '*' lines.
#include <iosfwd>

#include "fspm/mtg.hpp"

namespace fspm {

void write_mtg(const Mtg& mtg, std::ostream& out);

}  // namespace fspm
