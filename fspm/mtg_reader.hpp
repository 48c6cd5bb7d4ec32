#pragma once
// Reading MTG coding files (Godin and Caraglio 1998; the AMAPmod/VPlants syntax that OpenAlea's
// openalea.mtg.io.read_mtg reads) into a multiscale tree graph.
//
// The header: `CODE:` (FORM-A or FORM-B), `CLASSES:` (symbols of one or more letters and their
// scales; `$` is scale 0), `DESCRIPTION:` (allowed relations), `FEATURES:` (names and types: INT,
// REAL, ALPHA, STRING, DD/MM/YY, DD/MM/YYYY, MM/YY, DD/MM, GEOMETRY, APPEARANCE, OBJECT). Keywords
// may be followed by spaces before their colon (`MTG :`), `#` starts a comment.
//
// The code (`MTG:` then a header line starting with `ENTITY-CODE` or `TOPO` and naming the
// feature columns): one or more entities per line, each a relation and a label: `/` decomposition,
// `<` successor, `+` branch; `^` at the start of a cell continues the entity written last in the
// same column; a line one column to the right continues the line above it, a `+` or `/` there
// opening a branch that ends where the code comes back to the left (OpenAlea's reading of the
// columns). `E1<<E35` (and `++`) abbreviate a series of successors (branches) numbered 1 to 35,
// `<.<` and `+.+` the same with the line's features given to every entity of the series. A line
// whose code is `*` repeats the features of the entity above at another date (dynamic MTGs).
// Feature cells belong to the last entity of their line. Several plants (`/P1`, `/P2` ...) may
// follow one another.
//
// Mistakes that OpenAlea's reader cannot make sense of (an unknown symbol, a code that does not
// start with `/`, a column that matches none above, a scale skipped) throw ParseError with the
// file, line, column and entity code; doubtful but readable input (a value that is not of its
// feature's type, an unknown feature column) is reported in `warnings`.
#include <string>
#include <string_view>
#include <vector>

#include "fspm/mtg.hpp"

namespace fspm {

Mtg read_mtg(std::string_view text, const std::string& file = "<mtg>",
             std::vector<std::string>* warnings = nullptr);

// read_mtg of a file's contents; throws FileNotFoundError or IoError when it cannot be read.
Mtg read_mtg_file(const std::string& path, std::vector<std::string>* warnings = nullptr);

}  // namespace fspm
