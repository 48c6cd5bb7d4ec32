#pragma once
// Structures a tree had when young and has shed since (Pirk 2013, 5.3.5-5.3.6): the trunk below
// the crown of the given tree is bare, but a young tree of the same kind carries branches down
// to the ground. They are added to the branching graph as copies of the tree's own lateral
// branches (self-similarity) and removed again as the crown ratio falls with the tree's height
// (Pirk eq. 5.10), so that the last stage is the given tree.
//
// Built: the region below the crown on the main chain (Gravelius level 1), and optionally the
// overlap region above the crown base (5.3.5), filled where stratified clipping finds more tissue
// than main-axis cutting (5.3.4). Not built: the same filling on higher-level chains.
#include <cstdint>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::stages {

struct AddedStructuresParams {
  // Off by default: Pirk makes the structures part of his method, but they change every stage
  // before the crown base is reached, and a grown tree that never shed needs none.
  bool enabled = false;
  double crown_ratio_at_zero_height = 0.99;  // CR_0 of eq. 5.10 (Hasenauer and Monserud)
  double gamma = 1.0;  // eq. 5.10; != 1 moves the removal times (< 1 keeps some at t = 1)
  double scale = 1.0;  // size of each copy relative to its source branch
  // Pirk 5.3.5: also fill the overlap region, the main chain from the crown base up over the
  // length of the filled sub-crown region, with copies kept only on segments whose tissue above
  // T(z) by stratified clipping exceeds that by main-axis cutting by more than
  // `overlap_significance` (relative), or where both are below `overlap_low` (shares of the
  // whole tree). Off by default, like `enabled`.
  bool overlap = false;
  double overlap_layer_m = 0.0;  // Δz of the profile diagrams; 0: a twentieth of the height
  double overlap_significance = 0.1;
  double overlap_low = 0.05;
  void validate() const;  // throws ValueError for values out of range
};

// Crown shape of a tree (Pirk Table 5.1): height h = top of the internodes above the root's
// base, crown base = height of the lowest main-chain node that carries a live lateral (a leaf in
// its subtree; any lateral in a tree without leaves), crown ratio = (h - base) / h.
struct CrownShape {
  double height_m = 0.0;
  double crown_base_m = 0.0;
  NodeId crown_base_node = kNoNode;  // main-chain edge at whose end the crown begins
  double crown_ratio() const { return height_m > 0.0 ? (height_m - crown_base_m) / height_m : 1.0; }
};
// `chain` is the chain per node (0: the main chain, as DevelopmentalModel::chain()).
CrownShape crown_shape(const TreeGraph& tree, const std::vector<std::uint32_t>& chain);
// Height of the internodes of `tree` above the base of its root (0 for an empty tree).
double tree_height(const TreeGraph& tree);

// Pirk eq. 5.10: CR(h) = (1 / (1 + exp(-(c0 + c1 h))))^gamma, with c0 and c1 fitted (for
// gamma = 1) through CR(0) = CR_0 and CR(h_p) = CR_p of the given tree.
class CrownRatioCurve {
 public:
  CrownRatioCurve() = default;
  CrownRatioCurve(double cr_0, double height_p_m, double cr_p, double gamma = 1.0);
  double crown_ratio(double height_m) const;
  // Height below which a tree of this height has no crown: h (1 - CR(h)).
  double crown_base_m(double height_m) const;
  double c0() const { return c0_; }
  double c1() const { return c1_; }

 private:
  double c0_ = 0.0, c1_ = 0.0, gamma_ = 1.0;
};

// The given tree with copies of its crown's lateral branches appended on the bare trunk (their
// nodes come after the given ones, so removing them gives back the given ids).
struct AddedStructures {
  TreeGraph tree;
  NodeId first_added = kNoNode;  // nodes >= first_added are copies
  // Per node: the height above the root's base at which its copy is attached (copies only;
  // NaN for the given nodes).
  std::vector<double> attach_height_m;
  CrownShape crown;
  CrownRatioCurve curve;
  std::size_t copies = 0;  // added branches, both regions
  // Per node: 1 for the copies in the overlap region (empty without them). They are shed by
  // `overlap_curve`, eq. 5.10 fitted to the crown ratio whose base is the region's top.
  std::vector<std::uint8_t> in_overlap;
  CrownRatioCurve overlap_curve;
  std::size_t overlap_copies = 0;
  double overlap_top_m = 0.0;  // height of the overlap region's top (0: no region)
};

// Pirk 5.3.5: the live laterals of the main chain from the crown base up are copied, as one
// continuous block per copy and with as few copies as cover it, downward along the main chain
// onto the bare trunk below the crown base; copy k is turned about the vertical by k times the
// golden angle so that copies do not hide each other. With `overlap`, the laterals one copy
// block above the overlap region are copied down by the same offset into it, on the segments
// that pass the heuristic of 5.3.5 (decided once, on the given tree's profile diagrams).
AddedStructures add_structures(const TreeGraph& tree, const std::vector<std::uint32_t>& chain,
                               const AddedStructuresParams& params);

}  // namespace fspm::stages
