#pragma once
// PCD point sets (Point Cloud Library format, version 0.7): DATA ascii and DATA binary; the x, y,
// z fields are read, other fields skipped. DATA binary_compressed is refused with a ParseError.
#include <string>
#include <string_view>

#include "scans/point_set.hpp"

namespace fspm::scans {

PointSet read_pcd_points(const std::string& path);
PointSet parse_pcd_points(std::string_view data, const std::string& path);

}  // namespace fspm::scans
