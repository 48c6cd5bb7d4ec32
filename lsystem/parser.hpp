#pragma once
// Reader of cpfg `.l` files (L-studio / vlab, ABOP notation). See docs/lsystem-language.md.
#include <string>
#include <string_view>

#include "lsystem/lsystem.hpp"
#include "lsystem/preprocessor.hpp"

namespace fspm::lsystem {

// "derivation length:" (and --steps) above this is a typo, not a plan: a step costs at least a
// pass over the module string.
inline constexpr int kMaxDerivationLength = 1000000000;

// Throws IoError when the file cannot be read and ParseError (file:line:column, what was
// expected) on malformed input: unbalanced '[' ']' in an axiom or successor, branches nested
// deeper than kMaxTreeDepth, a misplaced or missing part of a production. ValueError when an
// override names a macro the grammar never uses.
LSystem parse_lsystem_file(const std::string& path, const MacroOverrides& overrides = {});
LSystem parse_lsystem(std::string_view text, const std::string& name = "<string>",
                      const MacroOverrides& overrides = {}, const std::string& include_dir = ".");
// From already preprocessed text.
LSystem parse_lsystem(const SourceText& source);

// Module names in strings: one character (cpfg: F1F1 is F 1 F 1), ?P ?H ?U ?L ?E, @x, ~x;
// with `numbered_names` (GreenLab files, detected when a predecessor is written B0, M12 ...) a
// letter followed by digits is one name.
std::string read_module_name(Cursor& cursor, bool numbered_names = false);

}  // namespace fspm::lsystem
