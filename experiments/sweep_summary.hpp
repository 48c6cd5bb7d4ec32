#pragma once
// What a sweep did to every metric: for each swept parameter and each of its values, the mean,
// sample standard deviation and count of every metric over the successful runs with that value
// (marginal over the other parameters). `fspm report` prints these as tables and plots each
// metric against each swept parameter.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "experiments/results_db.hpp"

namespace fspm::experiments {

// Mean and sample standard deviation (n - 1) by Welford's update (Knuth TAOCP vol. 2, 4.2.2).
struct Moments {
  std::size_t n = 0;
  double mean = 0.0;
  double m2 = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void add(double x);
  double sd() const;  // 0 for fewer than two values
  // mean - sd and mean + sd kept within [min, max], so a band of counts never goes below the
  // smallest count.
  double lower_band() const { return std::max(mean - sd(), min); }
  double upper_band() const { return std::min(mean + sd(), max); }
};

struct SweptValue {
  std::string text;                        // the value as the report prints it
  double number;                           // the value as a number; NaN for a text value
  std::map<std::string, Moments> metrics;  // over the successful runs with this value
};

struct SweptParameter {
  std::string name;
  std::vector<SweptValue> values;  // ascending by number when all are numbers, else first seen
  bool numeric() const;            // every value is a number
};

// One entry per swept parameter of `info` (file order); runs that failed, and metrics that are
// missing or not finite, are left out of the moments.
std::vector<SweptParameter> sweep_summary(const ExperimentInfo& info,
                                          const std::vector<RunRecord>& runs);

// The swept parameter that is the plants' age (`years` or `age`) when it has two values or more,
// else null. Metrics grow with age, so a mean over several ages describes none of them: reports
// give the other parameters' means per age.
const SweptParameter* age_parameter(const std::vector<SweptParameter>& summary);

// The runs whose `parameter` has the printed value `value`.
std::vector<RunRecord> runs_with(const std::vector<RunRecord>& runs, const std::string& parameter,
                                 const std::string& value);

// True for the metrics that time the software (unit s: run_time, grow_seconds, ...), which the
// report keeps apart from what the plants did.
bool is_timing_metric(const std::string& metric);

}  // namespace fspm::experiments
