#pragma once
// Writing point sets: .ply (binary little-endian, float x y z) or .xyz (text, one point a line),
// chosen by extension; atomic (no half-written file on failure). Throws ValueError for another
// extension, IoError when writing fails.
#include <string>

#include "scans/point_set.hpp"

namespace fspm::scans {

void write_point_set(const PointSet& points, const std::string& path);

}  // namespace fspm::scans
