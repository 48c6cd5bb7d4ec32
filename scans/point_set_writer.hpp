#pragma once
// Writing point sets: .ply (binary little-endian, float x y z; double when a coordinate lies
// beyond kPlyFloatLimitM of zero, where a float would keep only centimetres to decimetres) or
// .xyz (text, one point a line, full precision), chosen by extension; atomic (no half-written
// file on failure). Throws ValueError for another
// extension or an empty point set, IoError when writing fails.
#include <string>

#include "scans/point_set.hpp"

namespace fspm::scans {

inline constexpr double kPlyFloatLimitM = 1000.0;

void write_point_set(const PointSet& points, const std::string& path);

}  // namespace fspm::scans
