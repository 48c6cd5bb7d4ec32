#include "experiments/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fspm/attribute_names.hpp"
#include "fspm/tree_summary.hpp"

namespace fspm::experiments {

const std::vector<MetricInfo>& metric_catalog() {
  static const std::vector<MetricInfo> catalog = {
      {"nodes", "count", "nodes of the tree graph (internodes and organs)"},
      {"internodes", "count", "internode nodes"},
      {"leaves", "count", "leaf nodes"},
      {"tips", "count", "nodes without children"},
      {"max_order", "count", "highest branching order (0: trunk only)"},
      {"height", "length", "highest point of the tree above the base of the root"},
      {"crown_width", "length", "diameter of the ground projection of the tree"},
      {"crown_depth", "length", "top of the tree minus the lowest lateral or leaf"},
      {"total_length", "length", "summed length of all internodes"},
      {"leaf_area", "length^2", "summed area of the leaves (0 when the model gives none)"},
      {"biomass", "mass", "GreenLab GL1: total biomass produced, seed included (sum of Q(n))"},
      {"light_interception", "m^2",
       "grow, adapt: sum over leaf clusters of (1 - translucency) x pi r^2 x light at the cluster",
       false},
      {"sunlit_leaf_area", "m^2",
       "grow, adapt: leaf area of the clusters in the sun (sunlit fraction per cluster, real sky's "
       "sun or a zenith beam)",
       false},
      {"shaded_leaf_area", "m^2", "grow, adapt: leaf area of the clusters in the shade", false},
      {"star", "ratio",
       "grow, adapt: silhouette to total leaf area ratio averaged over the sky (0.5: no shade)",
       false},
      {"light_interception_efficiency", "ratio",
       "grow, adapt: light the leaves intercept against unshaded leaves of the same area", false},
      {"absorbed_par", "mol/day",
       "grow with a real sky (sky = {...}): PAR the tree's leaves absorb per day", false},
      {"pruned_nodes", "count", "grow set T, adapt: nodes pruned by the adaptation", false},
      {"tip_displacement", "m", "grow set T, adapt: mean distance the surviving tips moved", false},
      {"grow_seconds", "s", "grow: time of the growth model (set T: growth in the open)", false},
      {"adapt_seconds", "s", "grow set T, adapt: time of the adaptation (analysis not included)",
       false},
      {"analysis_seconds", "s",
       "adapt, stages: time of the analysis the run used (made once per analysis parameters)",
       false},
      {"stage_seconds", "s", "stages: time to compute the run's developmental stage", false},
      {"regrow_seconds", "s",
       "grow, set T with measure_regrowth = 1: time to grow the tree in the scene instead", false},
      {"distance_to_reference", "cost",
       "constrained edit distance to outputs.reference with the [distance] settings", false},
      {"run_time", "s", "wall-clock time of the model run (parse, derive, interpret)"},
  };
  return catalog;
}

const MetricInfo* find_metric(std::string_view name) {
  for (const MetricInfo& m : metric_catalog()) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::map<std::string, double> tree_metrics(const TreeGraph& tree) {
  const TreeSummary s = summarize(tree);
  double leaf_area = 0.0;
  if (tree.has_attribute(kLeafAreaAttribute)) {
    for (double a : tree.attribute(kLeafAreaAttribute)) leaf_area += a;
  }
  return {
      {"nodes", static_cast<double>(s.nodes)},
      {"internodes", static_cast<double>(s.internodes)},
      {"leaves", static_cast<double>(s.leaves)},
      {"tips", static_cast<double>(s.tips)},
      {"max_order", static_cast<double>(s.max_order)},
      {"height", s.height_m},
      {"crown_width", s.crown_width_m},
      {"crown_depth", s.crown_depth_m},
      {"total_length", s.total_length_m},
      {"leaf_area", leaf_area},
  };
}

}  // namespace fspm::experiments
