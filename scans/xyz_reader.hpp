#pragma once
// XYZ and CSV point sets: one point a line, x y z first (further columns ignored), separated by
// spaces, tabs or commas; '#' and '//' lines are comments. A first line that is not numeric is a
// CSV header: the columns named x, y, z (any case) are used, else the first three.
#include <string>
#include <string_view>

#include "scans/point_set.hpp"

namespace fspm::scans {

PointSet read_xyz_points(const std::string& path);
PointSet parse_xyz_points(std::string_view text, const std::string& path);

}  // namespace fspm::scans
