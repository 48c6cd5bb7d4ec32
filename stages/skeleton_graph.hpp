#pragma once
// The curve skeleton's connectivity: the joined vertices (stages/vertex_joining.hpp) are linked
// wherever a mesh edge links two of their members (the connectivity the joined vertex takes
// over, Pirk 5.2.1), and the minimum spanning tree of that graph by edge length (Kruskal) removes
// the cycles left by joining. A mesh made of separate closed tubes (one per branch, as
// `fspm mesh` writes by default) leaves one graph part per tube: parts are then linked by the
// shortest links between them: first those shorter than `link_radius`, then, for parts still
// apart, those shorter than twice that, and so on.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "stages/vertex_joining.hpp"

namespace fspm::stages {

using SkeletonEdge = std::pair<std::uint32_t, std::uint32_t>;

// The edges of a spanning tree over all joined vertices.
std::vector<SkeletonEdge> skeleton_spanning_tree(
    const JoinedVertices& joined, const std::vector<std::array<std::uint32_t, 3>>& triangles,
    double link_radius);

}  // namespace fspm::stages
