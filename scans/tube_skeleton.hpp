#pragma once
// The skeleton of branches given as ring polylines (scans/tube_rings.hpp), joined by geometry
// alone since exporters' group names carry no common scheme: the trunk is the thickest branch
// among those reaching down to the lowest end (within a tenth of the model's height); then,
// as in Prim's minimum spanning tree, the branch whose end comes nearest to a branch already
// joined is joined next, that end its base, at the nearest point of the joined branch's axis
// (a fork between two rings becomes a node of its own, its radius interpolated); a branch whose
// base ring lies beside the parent's axis (modelled from the parent's surface) forks where its
// axis continued backwards meets the parent's, and a bone joins the fork to its base. Node radii
// are the mean of the radii of the two rings a node joins; orders count forks from the trunk.
#include <string>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "scans/tube_rings.hpp"

namespace fspm::scans {

// Throws ValueError (naming `path`) when `branches` is empty.
TreeGraph tube_skeleton(const std::vector<RingPolyline>& branches, const std::string& path);

}  // namespace fspm::scans
