#pragma once
// Growth-based editing of selected branches (Pirk 2013, 5.4.1): edits bound to the time
// parameter of the developmental stages, applied to the model after its analysis.
//   - Age ("advanced scaling"): a branch made older by Δt shows at stage t what it would show at
//     t + Δt, with its lengths, sub-branch angles and radii of that time; younger for Δt < 0, so
//     that it is smaller at t = 1. Its parent branches take the changed radii (eq. 5.8).
//   - Copy ("advanced copy & translate"): a branch copied to the end of another internode, moved
//     rigidly (its base to the target's end, turned so that it meets the target as the source
//     meets its own parent), and bound to the time of its new place: it starts when its parent
//     chain reaches the target, at the age the source had when it started, so that a copy on a
//     younger part of the tree is younger at every stage, and an older one older.
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::stages {

// A branch is the lateral chain holding `branch` with everything it carries.
struct AgeEdit {
  NodeId branch = kNoNode;  // an internode of the given tree, off the main chain
  double delta_t = 0.0;     // in units of t (0.1: a tenth of the development); > 0 older
};

struct CopyEdit {
  NodeId branch = kNoNode;  // an internode of the given tree, off the main chain
  NodeId target = kNoNode;  // an internode of the given tree: the copy stands at its end
};

// Applied in this order: the age edits, then the copies (a copy takes its source's edited age).
struct BranchEdits {
  std::vector<AgeEdit> age;
  std::vector<CopyEdit> copy;
  bool empty() const { return age.empty() && copy.empty(); }
};

}  // namespace fspm::stages
