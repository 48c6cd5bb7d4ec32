#include "fspm/length_unit.hpp"

#include <string>

#include "fspm/error.hpp"
#include "fspm/name_table.hpp"

namespace fspm {
namespace {

constexpr NameTable<LengthUnit, 4> kLengthUnitNames{
    "unit",
    {{LengthUnit::kMetre, "m", "metres"},
     {LengthUnit::kDecimetre, "dm", "decimetres"},
     {LengthUnit::kCentimetre, "cm", "centimetres"},
     {LengthUnit::kMillimetre, "mm", "millimetres"}}};

}  // namespace

std::string_view length_unit_name(LengthUnit unit) { return kLengthUnitNames.name(unit); }

LengthUnit length_unit_from_name(std::string_view name, std::string_view what) {
  return kLengthUnitNames.from_name(name, what);
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
