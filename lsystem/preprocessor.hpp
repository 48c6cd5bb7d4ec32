#pragma once
// The subset of the C preprocessor that cpfg files rely on (cpfg runs them through cpp):
// comments, backslash line continuation, object-like and function-like #define, #undef,
// #if/#ifdef/#ifndef/#elif/#else/#endif (with defined()), #include "file". Output lines keep
// their original file and line so that later errors point at the source.
#include <map>
#include <string>
#include <string_view>

#include "lsystem/source_text.hpp"

namespace fspm::lsystem {

// NAME -> replacement text; these win over any #define of the same name in the files.
using MacroOverrides = std::map<std::string, std::string>;

// Reads and preprocesses a file; #include paths are relative to the including file.
// Throws IoError when a file cannot be read and ParseError on malformed directives.
SourceText preprocess_file(const std::string& path, const MacroOverrides& overrides = {});

// Preprocesses text named `name` (used in messages); includes are relative to `include_dir`.
SourceText preprocess_text(std::string_view text, const std::string& name,
                           const MacroOverrides& overrides = {},
                           const std::string& include_dir = ".");

}  // namespace fspm::lsystem
