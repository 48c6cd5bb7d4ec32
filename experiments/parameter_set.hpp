#pragma once
// The parameters of one run: names as written in the experiment file ("steps", "define.R") with
// integer, real or text values. Kept in name order so that every listing of a run is stable.
#include <cstdint>
#include <map>
#include <string>
#include <variant>

namespace fspm::experiments {

using ParameterValue = std::variant<std::int64_t, double, std::string>;
using ParameterSet = std::map<std::string, ParameterValue>;

// Exact text of a value: integers as integers, reals in their shortest round-trip form, text as
// is. Used for L-system #define overrides and CSV cells.
std::string parameter_text(const ParameterValue& value);

// The value as a real number; throws ValueError naming `name` when it is text.
double parameter_number(const ParameterValue& value, const std::string& name);

// The text of a text value; throws ValueError naming `name` when it is a number.
std::string parameter_string(const ParameterValue& value, const std::string& name);

// The value as an integer; throws ValueError naming `name` when it is text or a real with a
// fractional part.
std::int64_t parameter_integer(const ParameterValue& value, const std::string& name);

}  // namespace fspm::experiments
