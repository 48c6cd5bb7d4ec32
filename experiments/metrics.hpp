#pragma once
// The metrics a run can record, with their units (docs/experiments.md lists the definitions).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm::experiments {

struct MetricInfo {
  std::string_view name;
  std::string_view unit;
  std::string_view description;
  // Recorded when an experiment lists no metrics; false for metrics only some models give.
  bool by_default = true;
};

// Every known metric, in the order exports list them by default.
const std::vector<MetricInfo>& metric_catalog();
// nullptr when there is no metric of that name.
const MetricInfo* find_metric(std::string_view name);

// The name of the metric the runner fills in itself: wall-clock seconds of the model's run.
inline constexpr std::string_view kRunTimeMetric = "run_time";

// Structure and size of a tree: nodes, internodes, leaves, height, crown_width, crown_depth,
// total_length (lengths in the tree's unit: metres for GreenLab, turtle steps for L-systems).
std::map<std::string, double> tree_metrics(const TreeGraph& tree);

}  // namespace fspm::experiments
