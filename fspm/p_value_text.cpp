#include "fspm/p_value_text.hpp"

#include <cmath>

#include "fspm/number_text.hpp"

namespace fspm {

std::string format_p_value(double p) {
  if (!std::isfinite(p)) return "p undefined";
  if (p < 0.001) return "p < 0.001";
  return "p = " + format_significant(p, 2);
}

}  // namespace fspm
