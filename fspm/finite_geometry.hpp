#pragma once
// Tree files hold finite geometry only: a nan or infinite coordinate, length, radius or birth
// time is refused when read and when written, so it cannot travel silently between tools.
#include "fspm/tree_graph.hpp"

namespace fspm {

// The name of the first geometric field of node `n` that is nan or infinite ("start", "end",
// "direction", "length", "radius", "birth time"), or nullptr when all are finite.
const char* non_finite_geometry(const TreeGraph& tree, NodeId n);

// Throws ValueError naming `path`, the node and the field when any node has one.
void require_finite_geometry(const TreeGraph& tree, const std::string& path);

}  // namespace fspm
