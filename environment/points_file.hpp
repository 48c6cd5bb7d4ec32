#pragma once
// Point lists for `fspm light`: CSV with a header x,y,z; results as x,y,z,light,dx,dy,dz (and
// the PAR of a real sky).
#include <Eigen/Core>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "environment/daylight.hpp"
#include "environment/light_model.hpp"

namespace fspm::environment {

// Throws ParseError naming the file, line and what was expected for a bad header or row.
std::vector<Eigen::Vector3d> parse_points_csv(std::string_view text,
                                              const std::string& file_name = "<points>");
std::vector<Eigen::Vector3d> read_points_csv(const std::string& path);

void write_light_csv(std::ostream& out, std::span<const Eigen::Vector3d> points,
                     std::span<const LightSample> samples);
// The same with the PAR of a real sky: x,y,z,light,dx,dy,dz,par_umol_m2_s,daily_par_mol_m2.
void write_light_csv(std::ostream& out, std::span<const Eigen::Vector3d> points,
                     std::span<const LightSample> samples,
                     std::span<const DaylightSample> daylight);

}  // namespace fspm::environment
