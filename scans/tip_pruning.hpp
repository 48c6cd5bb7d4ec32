#pragma once
// Short side tips of a point skeleton removed: binning a shortest-path tree splits a bin's ring of
// points into pieces where the scan is patchy or noisy, and each piece starts a dead end a few
// bins long beside the branch it belongs to (Livny et al. 2010 remove such spurs in their
// refinement). A tip chain (the nodes from a tip back to the first fork) shorter than
// min_length_m is removed, once, so branches behind a removed tip stay; a chain that continues
// its parent's axis (the trunk's or a branch's top) is kept whatever its length.
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::scans {

// 1 for the nodes of the short side tips, 0 for the rest (the nodes without_short_tips keeps).
std::vector<std::uint8_t> short_tip_nodes(const TreeGraph& tree, double min_length_m);

TreeGraph without_short_tips(const TreeGraph& tree, double min_length_m);

}  // namespace fspm::scans
