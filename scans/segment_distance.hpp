#pragma once
// Shortest distance between two line segments (closest points by clamped parameters, as in
// Ericson, Real-Time Collision Detection, sec. 5.1.9).
#include <Eigen/Core>

namespace fspm::scans {

double segment_distance(const Eigen::Vector3d& p1, const Eigen::Vector3d& q1,
                        const Eigen::Vector3d& p2, const Eigen::Vector3d& q2);

}  // namespace fspm::scans
