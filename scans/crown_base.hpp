#pragma once
// The crown base of a scanned tree in the silvicultural sense: the height of the base of the lowest
// live branch, where its axis leaves the trunk's axis (where the branch meets the stem). The
// skeleton's fork node is a centroid of a bin of points at one geodesic distance from the root, and
// it moves by a bin (0.1-0.2 m) with how the graph reached the junction; the branch's own points do
// not. Each branch from the trunk that carries at least `min_branch_length_m` of skeleton is judged
// by the points of its first segments off the trunk's surface:
// - with an axis (the points' spread along their principal direction kMinAxisSpread times that
//   across, not within kMinForkAngleDeg of the trunk), the point of the trunk's axis nearest to
//   the branch's axis line;
// - else the low side of those points next to the trunk (their kBaseQuantile), which meets the
//   trunk at the branch's base;
// - without such points, the fork node.
#include <cstdint>
#include <optional>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/point_set.hpp"
#include "scans/qsm_cylinders.hpp"

namespace fspm::scans {

inline constexpr double kMinAxisSpread = 3.0;
inline constexpr double kMinForkAngleDeg = 15.0;
inline constexpr double kBaseQuantile = 0.02;

// The lowest branch base (a z coordinate) over the trunk's branches; none without such a branch.
// `cylinder_of_point` and `cylinders` from fit_qsm_cylinders on the same points and skeleton.
std::optional<double> crown_base_z(const PointSet& points, const TreeGraph& skeleton,
                                   const std::vector<std::uint32_t>& cylinder_of_point,
                                   const std::vector<QsmCylinder>& cylinders,
                                   double min_branch_length_m);

}  // namespace fspm::scans
