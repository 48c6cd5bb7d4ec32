#pragma once
// Point lists for `fspm light`: CSV with a header x,y,z; results as x,y,z,light,dx,dy,dz.
#include <Eigen/Core>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "environment/light_model.hpp"

namespace fspm::environment {

// Throws ParseError naming the file, line and what was expected for a bad header or row.
std::vector<Eigen::Vector3d> parse_points_csv(std::string_view text,
                                              const std::string& file_name = "<points>");
std::vector<Eigen::Vector3d> read_points_csv(const std::string& path);

void write_light_csv(std::ostream& out, std::span<const Eigen::Vector3d> points,
                     std::span<const LightSample> samples);

}  // namespace fspm::environment
