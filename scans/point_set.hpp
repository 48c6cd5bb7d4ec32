#pragma once
// A point set: the positions of a laser scan (or of mesh vertices), in metres, z up.
#include <Eigen/Core>
#include <vector>

namespace fspm::scans {

struct PointSet {
  std::vector<Eigen::Vector3d> points;
};

}  // namespace fspm::scans
