#pragma once
// Bounds on how deeply readers of nested formats (JSON, TOML, Newick, MTG, L-system brackets)
// let their input nest, so that a pathological file gets a clear error instead of exhausting
// the stack or the memory of code that walks the result recursively.
#include <string>
#include <string_view>

namespace fspm {

// JSON documents of the project (scenes, run records) nest a handful of levels.
inline constexpr int kMaxJsonDepth = 64;
// Trees (Newick parentheses, MTG code columns, L-system brackets) nest up to one level per
// node (a Newick chain); their readers and writers are iterative (tested to 200 000 levels),
// so this bound only stops input that is nothing but nesting.
inline constexpr int kMaxTreeDepth = 1000000;

// Throws ParseError (file, line, column of the bracket that goes one level too deep, and the
// limit) when '[' and '{' outside JSON strings nest deeper than `limit`.
void check_json_depth(std::string_view text, const std::string& file, int limit = kMaxJsonDepth);

// The message of a reader that met nesting deeper than `limit`, e.g. "nesting deeper than the
// limit of 64 levels (JSON arrays and objects)".
std::string nesting_too_deep(int limit, std::string_view what);

}  // namespace fspm
