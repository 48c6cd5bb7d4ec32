#pragma once
// Removing spurs from a curve skeleton: joining contracted vertices (eq. 5.1-5.2) and linking
// separate tubes leave short dead ends where tubes end or overlap (a trunk's end cap beyond the
// point where its laterals attach). A spur is a run of edges from an end to the first fork that
// is shorter than `min_length`; each is removed once (not repeatedly, so that the branches
// behind a removed spur are kept). Branches shorter than `min_length` in the mesh are lost too.
#include <Eigen/Core>
#include <vector>

#include "stages/skeleton_graph.hpp"

namespace fspm::stages {

// The edges without the spurs.
std::vector<SkeletonEdge> prune_spurs(const std::vector<SkeletonEdge>& edges,
                                      const std::vector<Eigen::Vector3d>& positions,
                                      double min_length);

}  // namespace fspm::stages
