#pragma once
// Branch diameters from allometry (Pirk eq. 3.1): d(u) = d_root (l(u) / l(root))^gamma, where l(u)
// sums the lengths of the edges of the subtree at u. Here the subtree of a skeleton node includes
// its own segment (the edge from its parent), so that tips get a non-zero diameter; l(root) is
// then the length of the whole skeleton.
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/point_skeleton.hpp"

namespace fspm::scans {

// l(u) for every node: its segment length plus those of all its descendants.
std::vector<double> subtree_lengths_m(const TreeGraph& tree);

// Sets every node's radius to d(u) / 2 of eq. 3.1 (requires d_root_m > 0 and gamma >= 0).
void set_allometric_radii(TreeGraph& tree, double d_root_m, double gamma);

// Sets the branching order: a node continues its parent's axis when it has the parent's
// largest subtree length among the siblings, else its order is one more.
void set_branch_orders(TreeGraph& tree);

// d_root from the trunk points: the points of the root node and of the nodes of the trunk up to
// `height_m` above the lowest point, a circle fitted to their horizontal positions (Kasa's
// algebraic least-squares fit, which tolerates the partial arcs a scan sees). Returns 0 when
// fewer than 5 points or no circle fits.
double estimate_root_diameter_m(const PointSet& points, const PointSkeleton& skeleton,
                                double height_m);

}  // namespace fspm::scans
