#pragma once
// "Did you mean ...?" for misspelled names (macros, keys, parameters).
#include <string>
#include <string_view>
#include <vector>

namespace fspm {

// The known name nearest to `name` by edit distance (ignoring case), or "" when `known` is
// empty or nothing is reasonably close (more than half of the letters differ).
std::string closest_name(std::string_view name, const std::vector<std::string>& known);

// " (did you mean 'X'?)" for the closest known name, or " (known: a, b, c)" when none is close,
// or "" when `known` is empty: a suffix for error messages.
std::string closest_name_hint(std::string_view name, const std::vector<std::string>& known);

// "unknown key 'age[0].phylotaxy' (did you mean 'phyllotaxy'?)": the one message every
// configuration reader (TOML and JSON) gives for a key it does not know. `qualified_key` names the
// key with its table, `key` alone is compared with the `known` keys of that table.
std::string unknown_key_message(std::string_view qualified_key, std::string_view key,
                                const std::vector<std::string>& known);

}  // namespace fspm
