#include "fspm/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "fspm/error.hpp"

namespace fspm {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void require(std::span<const double> v, std::size_t n, const char* what) {
  if (v.size() < n) {
    throw ValueError(std::string(what) + " needs at least " + std::to_string(n) + " values, got " +
                     std::to_string(v.size()));
  }
  for (const double x : v) {
    if (!std::isfinite(x)) throw ValueError(std::string(what) + ": values must be finite numbers");
  }
}

// Finite values whose squares or differences overflow (around 1e154 and beyond) give an infinite
// or nan spread: say so, rather than calling the data constant.
void require_no_overflow(bool finite, const char* what) {
  if (!finite) {
    throw ValueError(std::string(what) +
                     ": the values are too large (their spread overflows a double); rescale them");
  }
}

void check_level(double level) {
  if (!(level > 0.0 && level < 1.0)) {
    throw ValueError("confidence level must be in (0, 1), got " + std::to_string(level));
  }
}

// p-value and confidence interval of a t statistic `t` = estimate / se with `df` degrees of
// freedom.
void finish_t_test(TTestResult& r, double se, Alternative alt, double level) {
  check_level(level);
  require_no_overflow(std::isfinite(se) && std::isfinite(r.estimate), "t-test");
  if (!(se > 0.0)) {
    throw ValueError("t-test: the data are constant (zero standard error); t is undefined");
  }
  r.t = r.estimate / se;
  const boost::math::students_t dist(r.df);
  switch (alt) {
    case Alternative::kTwoSided: {
      r.p = 2.0 * boost::math::cdf(boost::math::complement(dist, std::abs(r.t)));
      const double q = boost::math::quantile(boost::math::complement(dist, (1.0 - level) / 2.0));
      r.confidence_interval = {r.estimate - q * se, r.estimate + q * se};
      break;
    }
    case Alternative::kLess: {
      r.p = boost::math::cdf(dist, r.t);
      const double q = boost::math::quantile(boost::math::complement(dist, 1.0 - level));
      r.confidence_interval = {-kInf, r.estimate + q * se};
      break;
    }
    case Alternative::kGreater: {
      r.p = boost::math::cdf(boost::math::complement(dist, r.t));
      const double q = boost::math::quantile(boost::math::complement(dist, 1.0 - level));
      r.confidence_interval = {r.estimate - q * se, kInf};
      break;
    }
  }
  r.p = std::min(r.p, 1.0);
}

TTestResult describe(std::span<const double> a, std::span<const double> b) {
  require(a, 2, "t-test sample a");
  require(b, 2, "t-test sample b");
  TTestResult r;
  r.n_a = a.size();
  r.n_b = b.size();
  r.mean_a = mean(a);
  r.mean_b = mean(b);
  r.sd_a = standard_deviation(a);
  r.sd_b = standard_deviation(b);
  r.estimate = r.mean_a - r.mean_b;
  return r;
}

double normal_cdf(double z) { return boost::math::cdf(boost::math::normal(), z); }

}  // namespace

std::string_view alternative_name(Alternative alternative) {
  return kAlternativeNames.name(alternative);
}

Alternative alternative_from_name(std::string_view name) {
  return kAlternativeNames.from_name(name);
}

double mean(std::span<const double> values) {
  require(values, 1, "mean");
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double variance(std::span<const double> values) {
  require(values, 2, "variance");
  // Two passes (mean, then squared deviations plus the rounding correction of the first pass):
  // exact to the last digits on NIST's NumAcc data where the one-pass formula fails.
  const double m = mean(values);
  double ss = 0.0, comp = 0.0;
  for (const double x : values) {
    ss += (x - m) * (x - m);
    comp += x - m;
  }
  const double n = static_cast<double>(values.size());
  return (ss - comp * comp / n) / (n - 1.0);
}

double standard_deviation(std::span<const double> values) { return std::sqrt(variance(values)); }

Interval mean_confidence_interval(std::span<const double> values, double level) {
  check_level(level);
  const double m = mean(values);
  const double se = standard_deviation(values) / std::sqrt(static_cast<double>(values.size()));
  const boost::math::students_t dist(static_cast<double>(values.size() - 1));
  const double q = boost::math::quantile(boost::math::complement(dist, (1.0 - level) / 2.0));
  return {m - q * se, m + q * se};
}

TTestResult student_t_test(std::span<const double> a, std::span<const double> b,
                           Alternative alternative, double level) {
  TTestResult r = describe(a, b);
  const double na = static_cast<double>(r.n_a), nb = static_cast<double>(r.n_b);
  r.df = na + nb - 2.0;
  const double pooled = ((na - 1.0) * r.sd_a * r.sd_a + (nb - 1.0) * r.sd_b * r.sd_b) / r.df;
  finish_t_test(r, std::sqrt(pooled * (1.0 / na + 1.0 / nb)), alternative, level);
  return r;
}

TTestResult welch_t_test(std::span<const double> a, std::span<const double> b,
                         Alternative alternative, double level) {
  TTestResult r = describe(a, b);
  const double na = static_cast<double>(r.n_a), nb = static_cast<double>(r.n_b);
  const double va = r.sd_a * r.sd_a / na, vb = r.sd_b * r.sd_b / nb;
  // Welch-Satterthwaite degrees of freedom.
  r.df = (va + vb) * (va + vb) / (va * va / (na - 1.0) + vb * vb / (nb - 1.0));
  finish_t_test(r, std::sqrt(va + vb), alternative, level);
  return r;
}

TTestResult paired_t_test(std::span<const double> a, std::span<const double> b,
                          Alternative alternative, double level) {
  if (a.size() != b.size()) {
    throw ValueError("paired t-test: the samples differ in length (" + std::to_string(a.size()) +
                     " and " + std::to_string(b.size()) + ")");
  }
  TTestResult r = describe(a, b);
  std::vector<double> diff(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) diff[i] = a[i] - b[i];
  r.estimate = mean(diff);
  r.df = static_cast<double>(diff.size()) - 1.0;
  finish_t_test(r, standard_deviation(diff) / std::sqrt(static_cast<double>(diff.size())),
                alternative, level);
  return r;
}

MannWhitneyResult mann_whitney_u_test(std::span<const double> a, std::span<const double> b,
                                      Alternative alternative, bool continuity_correction) {
  require(a, 1, "Mann-Whitney sample a");
  require(b, 1, "Mann-Whitney sample b");
  const std::size_t m = a.size(), n = b.size(), total = m + n;
  // Mid-ranks of the pooled sample.
  std::vector<std::pair<double, bool>> pooled;
  pooled.reserve(total);
  for (const double x : a) pooled.emplace_back(x, true);
  for (const double x : b) pooled.emplace_back(x, false);
  std::sort(pooled.begin(), pooled.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  double rank_sum_a = 0.0, tie_term = 0.0;
  bool ties = false;
  for (std::size_t i = 0; i < total;) {
    std::size_t j = i;
    while (j < total && pooled[j].first == pooled[i].first) ++j;
    const double mid_rank = (static_cast<double>(i + 1) + static_cast<double>(j)) / 2.0;
    const double t = static_cast<double>(j - i);
    if (j - i > 1) ties = true;
    tie_term += t * t * t - t;
    for (std::size_t k = i; k < j; ++k) {
      if (pooled[k].second) rank_sum_a += mid_rank;
    }
    i = j;
  }
  const double md = static_cast<double>(m), nd = static_cast<double>(n);
  MannWhitneyResult r;
  r.u = rank_sum_a - md * (md + 1.0) / 2.0;
  if (!ties && m < 50 && n < 50) {
    // Exact null distribution of U: every choice of m ranks out of m + n is equally likely.
    // ways[j][s] = number of j-subsets of the ranks seen so far with rank sum s.
    r.exact = true;
    const std::size_t max_sum = m * (2 * total - m + 1) / 2;
    std::vector<std::vector<double>> ways(m + 1, std::vector<double>(max_sum + 1, 0.0));
    ways[0][0] = 1.0;
    for (std::size_t k = 1; k <= total; ++k) {
      for (std::size_t j = std::min(k, m); j >= 1; --j) {
        for (std::size_t s = max_sum; s >= k; --s) ways[j][s] += ways[j - 1][s - k];
      }
    }
    const std::size_t offset = m * (m + 1) / 2;  // smallest rank sum
    const std::vector<double>& counts = ways[m];
    double all = 0.0;
    for (const double c : counts) all += c;
    const auto u_index = static_cast<std::size_t>(std::llround(r.u));
    double le = 0.0, ge = 0.0;
    for (std::size_t u = 0; u + offset <= max_sum; ++u) {
      if (u <= u_index) le += counts[u + offset];
      if (u >= u_index) ge += counts[u + offset];
    }
    le /= all;
    ge /= all;
    switch (alternative) {
      case Alternative::kTwoSided:
        r.p = std::min(1.0, 2.0 * (r.u > md * nd / 2.0 ? ge : le));
        break;
      case Alternative::kLess:
        r.p = le;
        break;
      case Alternative::kGreater:
        r.p = ge;
        break;
    }
    return r;
  }
  const double td = static_cast<double>(total);
  const double sigma = std::sqrt(md * nd / 12.0 * ((td + 1.0) - tie_term / (td * (td - 1.0))));
  if (!(sigma > 0.0)) throw ValueError("Mann-Whitney test: all values are tied");
  double z = r.u - md * nd / 2.0;
  double correction = 0.0;
  if (continuity_correction) {
    correction = alternative == Alternative::kTwoSided
                     ? (z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0))
                     : (alternative == Alternative::kGreater ? 0.5 : -0.5);
  }
  z = (z - correction) / sigma;
  switch (alternative) {
    case Alternative::kTwoSided:
      r.p = std::min(1.0, 2.0 * std::min(normal_cdf(z), normal_cdf(-z)));
      break;
    case Alternative::kLess:
      r.p = normal_cdf(z);
      break;
    case Alternative::kGreater:
      r.p = normal_cdf(-z);
      break;
  }
  return r;
}

double cohens_d(std::span<const double> a, std::span<const double> b) {
  require(a, 2, "Cohen's d sample a");
  require(b, 2, "Cohen's d sample b");
  const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
  const double pooled = ((na - 1.0) * variance(a) + (nb - 1.0) * variance(b)) / (na + nb - 2.0);
  require_no_overflow(std::isfinite(pooled) && std::isfinite(mean(a) - mean(b)), "Cohen's d");
  if (!(pooled > 0.0)) throw ValueError("Cohen's d: both samples are constant");
  return (mean(a) - mean(b)) / std::sqrt(pooled);
}

std::vector<double> holm_adjusted(std::span<const double> p) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!std::isnan(p[i])) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return p[x] < p[y]; });
  std::vector<double> adjusted(p.begin(), p.end());
  const double m = static_cast<double>(order.size());
  double running = 0.0;  // the step-down maximum keeps the adjusted p-values in order
  for (std::size_t k = 0; k < order.size(); ++k) {
    running = std::max(running, std::min(1.0, (m - static_cast<double>(k)) * p[order[k]]));
    adjusted[order[k]] = running;
  }
  return adjusted;
}

}  // namespace fspm
