#pragma once
// Self-organizing tree growth (Palubicki et al. 2009), the model Pirk 4.5.4 grows its sets O and G
// with. Each cycle (a year): every bud senses its light Q and optimal growth direction V (from the
// shadow grid, space colonization or the sky hemisphere: GrowthParams::light_model); light is
// summed basipetally; lateral branches whose light per supported internode falls below the
// pruning factor are shed; the resource alpha * Q_base is distributed acropetally by the extended
// Borchert-Honda model with apical control lambda; a bud receiving v grows a shoot v internodes
// long in round(v) metamers (Palubicki's continuous option), each heading from its default
// direction bent by phototropism and gravitropism (Pirk eq. 4.6-4.7); shoots stop where they would
// enter a solid obstacle. Deterministic per seed.
#include <cstddef>
#include <vector>

#include "environment/growth_params.hpp"
#include "environment/scene.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment {

struct GrowthResult {
  // Internodes (kind internode, birth_time = year of growth, order, pipe-model radius) followed by
  // the leaf clusters as kind leaf nodes under the last internode of their shoot (start = end =
  // cluster centre, radius = cluster radius, attribute "translucency"). Internodes carry the
  // attribute "light" (the light their bud sensed in the last cycle; nan, "no value", for nodes
  // that had no bud then); a cluster carries the light at its centre through the final clusters
  // as turbid media, its own included: the mean light of its leaves (record_leaf_light).
  TreeGraph tree;
  std::size_t internodes = 0;
  std::size_t clusters = 0;
  std::size_t shed = 0;   // internodes removed by shedding over the whole run
  std::size_t grown = 0;  // internodes created over the whole run (shed ones included)
  double height_m = 0.0;
  std::vector<Sphere> cluster_spheres;  // the final leaf clusters, for the light model
};

// Growth stopped by GrowthParams::max_internodes or max_height_m: the message gives the year, the
// size reached, the limit and the vigour parameters that drove it.
class GrowthLimitError : public ValueError {
 public:
  using ValueError::ValueError;
};

// Grows a tree at `base` (the first internode points up) in `scene` (its occluders shade and
// obstruct; its sky gives the brightest point). Throws ValueError for invalid parameters.
GrowthResult grow_tree(const GrowthParams& params, const Scene& scene = {},
                       const Eigen::Vector3d& base = Eigen::Vector3d::Zero());

}  // namespace fspm::environment
