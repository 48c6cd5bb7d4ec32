#pragma once
// Plant descriptions shared by the GreenLab tests.
#include <string>

#include "greenlab/plant_params.hpp"

namespace fspm::greenlab::testing {

inline std::string example_path(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/greenlab/" + name;
}

inline PlantParams example(const std::string& name) {
  return read_plant_params(example_path(name));
}

// One age-1 axis of `per_unit` metamers per cycle, each bearing `buds` buds of age 2; age-2 axes
// grow one metamer per cycle and never branch.
inline std::string two_age_plant(int cycles, int per_unit, int buds, double branching,
                                 double growth, double survival) {
  return "[plant]\ncycles = " + std::to_string(cycles) +
         "\n[[age]]\nindex = 1\nduration = 1000\nnext_age = 0\nunits = [ { count = " +
         std::to_string(per_unit) + ", axillary = [ { age = 2, count = " + std::to_string(buds) +
         " } ] } ]\ngrowth_probability = " + std::to_string(growth) +
         "\nsurvival_probability = " + std::to_string(survival) +
         "\n[[age]]\nindex = 2\nduration = 1000\nnext_age = 0\nunits = [ { count = 1 } ]\n"
         "branching_probability = " +
         std::to_string(branching) + "\n";
}

}  // namespace fspm::greenlab::testing
