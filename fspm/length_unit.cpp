#include "fspm/length_unit.hpp"

#include <string>

#include "fspm/error.hpp"

namespace fspm {

std::string_view length_unit_name(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre:
      return "m";
    case LengthUnit::kDecimetre:
      return "dm";
    case LengthUnit::kCentimetre:
      return "cm";
    case LengthUnit::kMillimetre:
      return "mm";
  }
  return "m";
}

LengthUnit length_unit_from_name(std::string_view name, std::string_view what) {
  for (LengthUnit u : {LengthUnit::kMetre, LengthUnit::kDecimetre, LengthUnit::kCentimetre,
                       LengthUnit::kMillimetre}) {
    if (length_unit_name(u) == name) return u;
  }
  throw ValueError(std::string(what) + ": unknown unit '" + std::string(name) +
                   "': expected m, dm, cm or mm");
}

double metres_per_unit(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMetre:
      return 1.0;
    case LengthUnit::kDecimetre:
      return 0.1;
    case LengthUnit::kCentimetre:
      return 0.01;
    case LengthUnit::kMillimetre:
      return 0.001;
  }
  return 1.0;
}

}  // namespace fspm
