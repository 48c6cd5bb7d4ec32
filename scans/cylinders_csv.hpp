#pragma once
// The cylinders of a quantitative structure model as CSV with TreeQSM's columns (Raumonen et al.
// 2013; TreeQSM's cylinder table): start_x, start_y, start_z, axis_x, axis_y, axis_z, length,
// radius, parent, branch, order, and fspm's nested (1: inside a wider cylinder, not counted in
// the volume). Metres; rows are cylinders numbered from 1 as in TreeQSM, parent 0 for the first,
// branches numbered from 1 (the trunk), order 0 for the trunk. Coordinates in full precision.
#include <string>
#include <vector>

#include "scans/qsm_cylinders.hpp"

namespace fspm::scans {

std::string cylinders_csv(const std::vector<QsmCylinder>& cylinders);
// Atomic; throws IoError when the file cannot be written.
void write_cylinders_csv(const std::vector<QsmCylinder>& cylinders, const std::string& path);

}  // namespace fspm::scans
