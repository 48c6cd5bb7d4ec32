#pragma once
// The code section of an MTG coding file (after "MTG:"): its table read into the vertices,
// relations and features of an Mtg whose header is already read. Used by fspm/mtg_reader.cpp.
#include <string>
#include <string_view>
#include <vector>

#include "fspm/mtg.hpp"

namespace fspm {

struct MtgLine {
  std::string_view text;
  int number = 0;  // from 1
};

// Reads lines[first...]: the column header (ENTITY-CODE or TOPO and the feature names), then the
// entities. Throws ParseError naming file:line:column and the entity code.
void read_mtg_code(const std::vector<MtgLine>& lines, std::size_t first, const std::string& file,
                   Mtg& mtg, std::vector<std::string>* warnings);

}  // namespace fspm
