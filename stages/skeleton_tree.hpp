#pragma once
// The tree graph of a curve skeleton: the spanning tree over the joined vertices
// (stages/skeleton_graph.hpp) rooted at its lowest end (the lowest joined vertex with at most one
// link: the base of the trunk), one internode per skeleton edge from parent to child.
// - Ends: a skeleton end (a tip, and the root) is moved out along its edge as far as the
//   original vertices of its group reach: the contraction pulls a tube's ends inward by about
//   half its radius, and the group's average (eq. 5.2) lies inside the branch by up to t_dist.
// - Radii: the mean distance from the original (uncontracted) mesh vertices of an edge's two
//   joined vertices to the edge's line, over those whose projection falls on the edge (the
//   others belong to the neighbouring edges or to an end cap); for an edge no vertex projects
//   onto, the mean distance of its child's original vertices to the child.
// When the root has more than one link, the extra branches hang from the first internode.
#include <Eigen/Core>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "stages/skeleton_graph.hpp"
#include "stages/vertex_joining.hpp"

namespace fspm::stages {

// `original`: the mesh's vertices before contraction. Needs at least two joined
// vertices (throws ValueError otherwise).
TreeGraph skeleton_tree(const JoinedVertices& joined, const std::vector<SkeletonEdge>& edges,
                        const std::vector<Eigen::Vector3d>& original);

}  // namespace fspm::stages
