#pragma once
// Light against height in the crown: the mean light of a tree's leaf clusters (their attribute
// "light", the mean light of each cluster's leaves relative to the open sky) in horizontal
// layers of equal thickness from the lowest cluster to the highest, as a plant physiologist plots
// a canopy's light profile.
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::environment {

struct LightLayer {
  double height_m = 0.0;    // middle of the layer above the tree's base (its first node's start)
  double mean_light = 0.0;  // over the clusters whose centre lies in the layer
  int clusters = 0;
};

// `layers` layers (at least 1) of the live leaf clusters with a finite "light"; layers without a
// cluster are left out. Empty when the tree has no such cluster.
std::vector<LightLayer> leaf_light_profile(const TreeGraph& tree, int layers = 10);

}  // namespace fspm::environment
