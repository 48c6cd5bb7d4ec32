#pragma once
// Parallel transport frames (Hanson and Ma 1995, as given in Pirk 2014, section 6.1.2): a normal
// vector is carried along a polyline by the smallest rotation between consecutive tangents, so
// frames stay continuous on straight runs where Frenet frames are undefined.
#include <Eigen/Core>
#include <span>
#include <vector>

namespace fspm::graphics {

// Rotation by `theta_rad` about the unit axis `n` (Pirk eq. 6.5).
Eigen::Matrix3d rotation_about_axis(const Eigen::Vector3d& n, double theta_rad);

// Carries `v` from the unit tangent `t_from` to the unit tangent `t_to`: rotation about
// B = t_from x t_to (eq. 6.2) by theta = acos(t_from . t_to) (eq. 6.3), applied as eq. 6.4.
// Parallel tangents leave `v` unchanged (Pirk Algorithm 1, line 4).
Eigen::Vector3d transport(const Eigen::Vector3d& v, const Eigen::Vector3d& t_from,
                          const Eigen::Vector3d& t_to);

// Pirk Algorithm 1: normals V_0..V_N for unit tangents T_0..T_N, V_0 = `v0` projected
// perpendicular to T_0 and normalised.
std::vector<Eigen::Vector3d> parallel_transport_normals(std::span<const Eigen::Vector3d> tangents,
                                                        const Eigen::Vector3d& v0);

// Some unit vector perpendicular to the unit vector `t` (used to start a frame).
Eigen::Vector3d any_perpendicular(const Eigen::Vector3d& t);

}  // namespace fspm::graphics
