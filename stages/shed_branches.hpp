#pragma once
// Branches shed before the given tree, reconstructed from the pipe model (Shinozaki et al. 1964).
// A branch is a bundle of pipes, one per leaf unit (tip); when a branch is shed its pipes stay in
// the wood below as disused pipes, so an edge whose radius exceeds what its children need,
// r_p^u > sum r_i^u (b_p > 1 in Pirk eq. 5.7), lost branches holding the difference. In units of
// the tip's pipe r_tip^u the difference is the number of tips the shed branches had.
//
// The developmental model (StagesParams::shed) stands one shed branch at each such edge: a copy
// of the given tree's lateral whose pipes are closest to the difference (self-similarity, as the
// added structures of Pirk 5.3.5), among the laterals that started later than the edge's end is
// reached, so that the copy runs on the clock of a branch of its size: it starts when its parent
// chain reaches the edge, grows as its source grew, and is shed when complete (when it has the
// pipes it left behind). It counts in the radii below it as long as it stands and after (eq. 5.8).
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::stages {

struct ShedBranchesParams {
  bool enabled = false;
  // Pipes beyond the children's needs, in tip pipes, that imply a shed branch: half a tip's pipe
  // (rounding and measurement noise stay below it on trees that follow the pipe model).
  double min_pipes = 0.5;
  void validate() const;  // throws ValueError
};

// An edge of the given tree with pipes beyond its children's needs.
struct ShedSite {
  NodeId edge = kNoNode;
  double pipes = 0.0;  // (r_p^u - sum r_i^u) / r_tip^u
};

// The edges with internode children whose radius holds at least `min_pipes` tip pipes more than
// their internode children need, in id order. Tips (no internode child) are not sites.
std::vector<ShedSite> find_shed_sites(const TreeGraph& tree, double pipe_exponent,
                                      double tip_radius_m, double min_pipes);

// A lateral of the given tree that a shed branch may copy.
struct ShedSource {
  NodeId base = kNoNode;  // first edge of the lateral chain
  double pipes = 0.0;     // r_base^u / r_tip^u
  double start = 0.0;     // the time its chain starts
};

// Of `sources` (sorted by pipes), the one whose pipes are closest to `pipes` in ratio among
// those starting after `reached`; the closest of all if none does. kNoNode if there is none.
NodeId choose_shed_source(const std::vector<ShedSource>& sources, double pipes, double reached);

}  // namespace fspm::stages
