#pragma once
// Refinement of branch axes by uniform cubic B-splines (Pirk 2013, section 6.1.4, eq. 6.6-6.7):
// between P_i and P_{i+1} of a chain,
//   S_i(t) = [t^3 t^2 t 1] 1/6 [[-1 3 -3 1] [3 -6 3 0] [-3 0 3 0] [1 4 1 0]] [P_{i-1} P_i P_{i+1}
//   P_{i+2}]
// for t in [0, 1]. Only points of one chain are interpolated (not across the junction of two
// chains: Pirk keeps "the overall structure of the graph"); beyond the chain's ends the end
// points are reflected through their neighbours (P_{-1} = 2 P_0 - P_1), so the refined chain
// starts and ends at the chain's own ends. Between them the curve approximates rather than
// interpolates: S_i(0) = (P_{i-1} + 4 P_i + P_{i+1}) / 6.
#include <Eigen/Core>
#include <vector>

namespace fspm::graphics {

// Eq. 6.7 for one segment.
Eigen::Vector3d cubic_bspline(const Eigen::Vector3d& p_before, const Eigen::Vector3d& p0,
                              const Eigen::Vector3d& p1, const Eigen::Vector3d& p_after, double t);

// The chain's points refined into `subdivisions` (>= 1) pieces per segment: (n - 1) s + 1 points
// from S_0(0) to S_{n-2}(1). Fewer than two points come back unchanged. Throws ValueError for
// subdivisions < 1.
std::vector<Eigen::Vector3d> refine_chain(const std::vector<Eigen::Vector3d>& points,
                                          int subdivisions);

}  // namespace fspm::graphics
