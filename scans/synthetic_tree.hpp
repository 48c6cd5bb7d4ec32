#pragma once
// A parametric tree with a known skeleton, for validating the encoder on simulated scans and for
// benchmarks: a vertical trunk of trunk_length_m, `branches` main branches spaced evenly over its
// upper part (137.5 degree divergence, 50 degrees from vertical), each with `twigs` side twigs.
// All internodes are internode_length_m long (rounded to whole internodes per axis), and radii
// follow Pirk eq. 3.1 on the tree itself, d(u) = d_root (l(u) / l(root))^gamma.
#include "fspm/tree_graph.hpp"

namespace fspm::scans {

struct SyntheticTreeOptions {
  double trunk_length_m = 5.0;
  double branch_length_m = 2.0;
  double twig_length_m = 0.8;
  int branches = 4;
  int twigs = 2;
  double internode_length_m = 0.25;
  double root_diameter_m = 0.3;
  double gamma = 1.5;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

TreeGraph synthetic_tree(const SyntheticTreeOptions& options = {});

}  // namespace fspm::scans
