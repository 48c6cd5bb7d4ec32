#include "experiments/parameter_set.hpp"

#include <cmath>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm::experiments {

std::string parameter_text(const ParameterValue& value) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* d = std::get_if<double>(&value)) {
    std::string out;
    append_number(out, *d);
    return out;
  }
  return std::get<std::string>(value);
}

double parameter_number(const ParameterValue& value, const std::string& name) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&value)) return *d;
  throw ValueError("parameter '" + name + "' must be a number, not the text '" +
                   std::get<std::string>(value) + "'");
}

std::string parameter_string(const ParameterValue& value, const std::string& name) {
  if (const auto* s = std::get_if<std::string>(&value)) return *s;
  throw ValueError(name + " must be text, not the number " + parameter_text(value));
}

std::int64_t parameter_integer(const ParameterValue& value, const std::string& name) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return *i;
  const double d = parameter_number(value, name);
  if (!std::isfinite(d) || std::floor(d) != d || std::fabs(d) > 9.0e15) {
    throw ValueError("parameter '" + name + "' must be an integer, not " + parameter_text(value));
  }
  return static_cast<std::int64_t>(d);
}

}  // namespace fspm::experiments
