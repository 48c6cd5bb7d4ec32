#pragma once
// Writing a multiscale tree graph as an MTG coding file that read_mtg (and OpenAlea's reader)
// reads back to the same graph: the header (CODE, CLASSES, DESCRIPTION, FEATURES), then one line
// per entity with its features. An axis stays in one column ('^<' continues it, '^/' descends
// into the first component of the entity above); a branch ('+') opens the next column to the
// right; dated repetitions follow their entity as '*' lines.
#include <cstdint>
#include <iosfwd>
#include <string>

#include "fspm/mtg.hpp"

namespace fspm {

// The largest MTG code the writers make (check_mtg_code_size).
inline constexpr std::uint64_t kMaxMtgCodeBytes = std::uint64_t{256} << 20;

// `path` names the output in errors; `max_code_bytes` bounds the code (check_mtg_code_size).
void write_mtg(const Mtg& mtg, std::ostream& out, const std::string& path = {},
               std::uint64_t max_code_bytes = kMaxMtgCodeBytes);

// MTG indents every level of nested branching by one tab and starts the features after the
// deepest level, so a chain of 200 000 branches on branches (50 bytes with the "+.+" notation)
// would take tens of gigabytes: a code of more than `max_bytes` (256 MiB) is refused (ValueError
// naming `path`, the output, and the size) before anything is written. `bytes` is the code's
// size, `columns` its deepest level.
void check_mtg_code_size(std::uint64_t bytes, int columns, const std::string& path,
                         std::uint64_t max_bytes = kMaxMtgCodeBytes);

}  // namespace fspm
