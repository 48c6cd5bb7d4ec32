#pragma once
// Units of lengths in measured plant files (MTG features, coordinates): metres, decimetres,
// centimetres, millimetres. fspm works in metres; a reader multiplies by metres_per_unit.
#include <string_view>

namespace fspm {

enum class LengthUnit { kMetre, kDecimetre, kCentimetre, kMillimetre };

// "m", "dm", "cm", "mm".
std::string_view length_unit_name(LengthUnit unit);
// Inverse of length_unit_name; throws ValueError naming `what` (an option) and the choices.
LengthUnit length_unit_from_name(std::string_view name, std::string_view what = "length unit");
double metres_per_unit(LengthUnit unit);

}  // namespace fspm
