#pragma once
// The comparisons an experiment file asks for after its runs (docs/experiments.md): pairs of runs
// compared by the constrained edit distance, t-tests between groups of such distances (Pirk
// 4.5.4) and summary tables of metrics. Parsed with the experiment; carried out by
// experiments/comparisons.hpp.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/parameter_set.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/statistics.hpp"

namespace fspm::experiments {

// Runs whose parameters equal every given value (compared by their text, "20" matches 20).
using RunFilter = ParameterSet;

// Which distance the t-tests and the report's tables compare: the normalized one (0 identical,
// 1 nothing in common; fspm/constrained_edit_distance.hpp), which does not grow with the size of
// the trees, or the raw one (Pirk's Table 4.1).
enum class DistanceScale { kNormalized, kRaw };
inline constexpr DistanceScale kDistanceScales[] = {DistanceScale::kNormalized,
                                                    DistanceScale::kRaw};
// "normalized", "raw".
inline std::string_view distance_scale_name(DistanceScale s) {
  return s == DistanceScale::kRaw ? "raw" : "normalized";
}

// How two kept trees are compared (fspm distance's options).
struct DistanceSpec {
  EditCostKind cost = EditCostKind::kStandardized;
  DistanceScale tested = DistanceScale::kNormalized;
  std::vector<std::string> attributes;  // empty: the cost model's defaults
  std::optional<double> main_skeleton_radius_m;
};

// [[comparison]]: `pairs` pairs (a, b), a drawn from the runs matching `a`, b from those matching
// `b`, no run used twice within the comparison; drawn separately within every combination of the
// `within` parameters' values, among the runs that also match `where`.
struct ComparisonSpec {
  std::string name;
  RunFilter a;
  RunFilter b;
  RunFilter where;
  std::vector<std::string> within;
  std::size_t pairs = 0;  // 0: as many as the runs allow
  int line = 0;
};

// [[ttest]]: the distances of comparison `a` against those of comparison `b`, per `within` group.
struct TTestSpec {
  std::string a;
  std::string b;
  bool welch = false;
  Alternative alternative = Alternative::kTwoSided;
  double alpha = 0.05;
  int line = 0;
};

// [[table]]: mean and standard deviation of metrics over the successful runs matching `where`,
// one row per combination of the `by` parameters' values.
struct SummaryTableSpec {
  std::string title;
  RunFilter where;
  std::vector<std::string> by;
  std::vector<std::string> metrics;
  int line = 0;
};

// [report]: the trees `fspm report` renders. The successful runs matching `where` are grouped by
// the `by` parameters' values (default: every swept and sampled parameter, one group per point);
// from each group the run whose `metric` is the group's (lower) median is drawn; at most `renders`
// groups, spread evenly from the first to the last in grid order.
struct RenderSpec {
  std::size_t renders = 6;  // 0: none
  std::vector<std::string> by;
  bool by_given = false;  // `by = []` puts every run in one group
  RunFilter where;
  std::string metric;  // empty: the first recorded metric
};

}  // namespace fspm::experiments
