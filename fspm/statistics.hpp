#pragma once
// Statistics for comparing groups of measurements (Pirk sec. 4.5.4 compares groups of tree
// distances with two-tailed t-tests), on Boost.Math distributions: mean, standard deviation,
// confidence intervals, Student, Welch and paired t-tests, the Mann-Whitney U test, Cohen's d.
// Conventions follow R's t.test and wilcox.test, so results can be checked against them.
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "fspm/name_table.hpp"

namespace fspm {

// The alternative hypothesis about mean_a - mean_b (or the location shift of a against b).
enum class Alternative { kTwoSided, kLess, kGreater };

inline constexpr NameTable<Alternative, 3> kAlternativeNames{
    "alternative",
    {{Alternative::kTwoSided, "two-sided", "a and b differ"},
     {Alternative::kLess, "less", "a below b"},
     {Alternative::kGreater, "greater", "a above b"}}};
inline constexpr auto kAlternatives = kAlternativeNames.values();
// "two-sided", "less", "greater".
std::string_view alternative_name(Alternative alternative);
// Inverse of alternative_name; throws ValueError on an unknown name.
Alternative alternative_from_name(std::string_view name);

struct Interval {
  double low = 0.0;
  double high = 0.0;
};

// Arithmetic mean; ValueError on an empty sample.
double mean(std::span<const double> values);
// Sample variance and standard deviation (divisor n - 1, two-pass for accuracy); ValueError when
// there are fewer than two values.
double variance(std::span<const double> values);
double standard_deviation(std::span<const double> values);
// The confidence level of intervals when none is asked for.
inline constexpr double kDefaultConfidenceLevel = 0.95;

// Student-t confidence interval of the mean at `level` (e.g. 0.95), two-sided.
Interval mean_confidence_interval(std::span<const double> values,
                                  double level = kDefaultConfidenceLevel);

struct TTestResult {
  double t = 0.0;
  double df = 0.0;
  double p = 0.0;
  double mean_a = 0.0, mean_b = 0.0;
  double sd_a = 0.0, sd_b = 0.0;
  std::size_t n_a = 0, n_b = 0;
  // Estimate of mean_a - mean_b (mean of the differences for the paired test) and its confidence
  // interval at the requested level: two-sided, or one-sided with an infinite end.
  double estimate = 0.0;
  Interval confidence_interval;
};

// Two-sample t-test assuming equal variances (pooled variance, df = n_a + n_b - 2).
TTestResult student_t_test(std::span<const double> a, std::span<const double> b,
                           Alternative alternative = Alternative::kTwoSided,
                           double level = kDefaultConfidenceLevel);
// Welch's t-test (unequal variances, Welch-Satterthwaite degrees of freedom).
TTestResult welch_t_test(std::span<const double> a, std::span<const double> b,
                         Alternative alternative = Alternative::kTwoSided,
                         double level = kDefaultConfidenceLevel);
// Paired t-test on the differences a_i - b_i (same length, at least two pairs).
TTestResult paired_t_test(std::span<const double> a, std::span<const double> b,
                          Alternative alternative = Alternative::kTwoSided,
                          double level = kDefaultConfidenceLevel);

struct MannWhitneyResult {
  double u = 0.0;  // U of sample a: pairs with a > b, plus one half per tie (R's W)
  double p = 0.0;
  bool exact = false;  // exact null distribution (no ties, both samples < 50) or normal
};

// Mann-Whitney U (Wilcoxon rank-sum) test. Exact p-value when there are no ties and both samples
// have fewer than 50 values; otherwise the normal approximation with tie correction and, when
// `continuity_correction`, the 0.5 continuity correction (as R's wilcox.test).
MannWhitneyResult mann_whitney_u_test(std::span<const double> a, std::span<const double> b,
                                      Alternative alternative = Alternative::kTwoSided,
                                      bool continuity_correction = true);

// Cohen's d: (mean_a - mean_b) / pooled standard deviation (divisor n_a + n_b - 2).
double cohens_d(std::span<const double> a, std::span<const double> b);

// Holm's step-down adjustment of a family of p-values (Holm 1979): sorted ascending, the i-th
// smallest (i from 0) becomes max over j <= i of min(1, (m - j) p_(j)), m the number of finite
// p-values; rejecting where the adjusted p < alpha keeps the family-wise error rate at alpha.
// Same order as the input; a NaN p stays NaN and is not counted in m (R's p.adjust "holm").
std::vector<double> holm_adjusted(std::span<const double> p);

}  // namespace fspm
