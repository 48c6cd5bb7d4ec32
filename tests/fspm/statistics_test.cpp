// Statistics against published reference values: NIST StRD univariate summary statistics
// (certified values), R's documented outputs on Student's sleep data (Cushny and Peebles 1905,
// R datasets::sleep) and Hollander and Wolfe's permeability example (R ?wilcox.test), and exact
// closed forms.
#include "fspm/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fspm/error.hpp"

namespace fspm {
namespace {

const std::vector<double> kSleep1{0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
const std::vector<double> kSleep2{1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};

// NIST StRD NumAcc1: certified mean 10000002, standard deviation 1.
TEST(Statistics, NistNumAcc1) {
  const std::vector<double> x{10000001, 10000003, 10000002};
  EXPECT_DOUBLE_EQ(mean(x), 10000002.0);
  EXPECT_DOUBLE_EQ(standard_deviation(x), 1.0);
}

// NIST StRD NumAcc3 and NumAcc4: 1001 values, c + 0.2 then (c + 0.1, c + 0.3) 500 times;
// certified mean c + 0.2 and standard deviation 0.1 (c = 1e6 and 1e7). The one-pass textbook
// formula loses most digits here.
TEST(Statistics, NistNumAcc3And4) {
  for (const double c : {1000000.0, 10000000.0}) {
    std::vector<double> x{c + 0.2};
    for (int i = 0; i < 500; ++i) {
      x.push_back(c + 0.1);
      x.push_back(c + 0.3);
    }
    EXPECT_NEAR(mean(x), c + 0.2, 1e-9 * c);
    EXPECT_NEAR(standard_deviation(x), 0.1, 1e-7) << c;
  }
}

// R: t.test(extra ~ group, data = sleep) -> t = -1.8608, df = 17.776, p-value = 0.07939,
// 95 percent confidence interval -3.3654832 0.2054832, means 0.75 and 2.33.
TEST(Statistics, WelchOnSleepData) {
  const auto r = welch_t_test(kSleep1, kSleep2);
  EXPECT_NEAR(r.t, -1.8608, 5e-5);
  EXPECT_NEAR(r.df, 17.776, 5e-4);
  EXPECT_NEAR(r.p, 0.07939, 5e-6);
  EXPECT_NEAR(r.confidence_interval.low, -3.3654832, 5e-8);
  EXPECT_NEAR(r.confidence_interval.high, 0.2054832, 5e-8);
  EXPECT_NEAR(r.mean_a, 0.75, 1e-12);
  EXPECT_NEAR(r.mean_b, 2.33, 1e-12);
  EXPECT_EQ(r.n_a, 10u);
  // One-tailed: half of the two-tailed p on the side of the observed t.
  EXPECT_NEAR(welch_t_test(kSleep1, kSleep2, Alternative::kLess).p, 0.07939 / 2, 3e-6);
  EXPECT_NEAR(welch_t_test(kSleep1, kSleep2, Alternative::kGreater).p, 1 - 0.07939 / 2, 3e-6);
  EXPECT_TRUE(
      std::isinf(welch_t_test(kSleep1, kSleep2, Alternative::kLess).confidence_interval.low));
}

// R: t.test(extra ~ group, data = sleep, var.equal = TRUE) -> t = -1.8608, df = 18,
// p-value = 0.07919, 95 percent confidence interval -3.363874 0.203874.
TEST(Statistics, StudentOnSleepData) {
  const auto r = student_t_test(kSleep1, kSleep2);
  EXPECT_NEAR(r.t, -1.8608, 5e-5);
  EXPECT_EQ(r.df, 18.0);
  EXPECT_NEAR(r.p, 0.07919, 5e-6);
  EXPECT_NEAR(r.confidence_interval.low, -3.363874, 5e-7);
  EXPECT_NEAR(r.confidence_interval.high, 0.203874, 5e-7);
}

// R: t.test(extra[group == 1], extra[group == 2], paired = TRUE) -> t = -4.0621, df = 9,
// p-value = 0.002833, 95 percent confidence interval -2.4598858 -0.7001142, mean difference
// -1.58.
TEST(Statistics, PairedOnSleepData) {
  const auto r = paired_t_test(kSleep1, kSleep2);
  EXPECT_NEAR(r.t, -4.0621, 5e-5);
  EXPECT_EQ(r.df, 9.0);
  EXPECT_NEAR(r.p, 0.002833, 5e-7);
  EXPECT_NEAR(r.estimate, -1.58, 1e-12);
  EXPECT_NEAR(r.confidence_interval.low, -2.4598858, 5e-8);
  EXPECT_NEAR(r.confidence_interval.high, -0.7001142, 5e-8);
  // The same interval is the one-sample interval of the differences.
  std::vector<double> diff;
  for (std::size_t i = 0; i < kSleep1.size(); ++i) diff.push_back(kSleep1[i] - kSleep2[i]);
  const auto ci = mean_confidence_interval(diff, 0.95);
  EXPECT_NEAR(ci.low, -2.4598858, 5e-8);
  EXPECT_NEAR(ci.high, -0.7001142, 5e-8);
}

// Cohen's d with the pooled standard deviation equals the Student t times sqrt(1/n_a + 1/n_b);
// with R's published t = -1.8608 that is -0.83218 (+- 2.3e-5 from t's rounding).
TEST(Statistics, CohensDFromPublishedT) {
  EXPECT_NEAR(cohens_d(kSleep1, kSleep2), -1.8608 * std::sqrt(0.2), 2.5e-5);
}

// R ?wilcox.test, Hollander and Wolfe (1973), p. 69f: permeability constants;
// wilcox.test(x, y, alternative = "g") -> W = 35, p-value = 0.1272 (exact).
TEST(Statistics, MannWhitneyExactPermeability) {
  const std::vector<double> x{0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46};
  const std::vector<double> y{1.15, 0.88, 0.90, 0.74, 1.21};
  const auto r = mann_whitney_u_test(x, y, Alternative::kGreater);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.u, 35.0);
  EXPECT_NEAR(r.p, 0.1272, 5e-5);
}

// Closed form: when every a exceeds every b, U = m n and P(U >= m n) = 1 / C(m + n, m).
TEST(Statistics, MannWhitneyExactExtreme) {
  const std::vector<double> a{10, 11, 12}, b{1, 2, 3, 4};
  const auto g = mann_whitney_u_test(a, b, Alternative::kGreater);
  EXPECT_EQ(g.u, 12.0);
  EXPECT_NEAR(g.p, 1.0 / 35.0, 1e-15);
  EXPECT_NEAR(mann_whitney_u_test(a, b).p, 2.0 / 35.0, 1e-15);
  EXPECT_NEAR(mann_whitney_u_test(a, b, Alternative::kLess).p, 1.0, 1e-15);
}

// R: wilcox.test(extra ~ group, data = sleep) -> W = 25.5, p-value = 0.06933 (ties: normal
// approximation with continuity correction).
TEST(Statistics, MannWhitneyNormalWithTiesOnSleepData) {
  const auto r = mann_whitney_u_test(kSleep1, kSleep2);
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.u, 25.5);
  EXPECT_NEAR(r.p, 0.06933, 5e-6);
}

TEST(Statistics, RejectsBadInput) {
  const std::vector<double> one{1.0}, constant{2.0, 2.0, 2.0};
  EXPECT_THROW(standard_deviation(one), ValueError);
  EXPECT_THROW(mean(std::vector<double>{}), ValueError);
  EXPECT_THROW(welch_t_test(one, kSleep2), ValueError);
  EXPECT_THROW(paired_t_test(kSleep1, constant), ValueError);
  EXPECT_THROW(student_t_test(constant, constant), ValueError);
  EXPECT_THROW(alternative_from_name("both"), ValueError);
  EXPECT_THROW(mean_confidence_interval(kSleep1, 1.5), ValueError);
}

}  // namespace
}  // namespace fspm

namespace fspm {
namespace {

// Holm 1979 by hand: sorted p times m, m - 1, ..., 1, then the running maximum, capped at 1.
TEST(Statistics, HolmAdjustmentByHand) {
  const std::vector<double> p{0.01, 0.02, 0.03, 0.04, 0.05};
  const std::vector<double> holm = holm_adjusted(p);
  const std::vector<double> expected{0.05, 0.08, 0.09, 0.09, 0.09};  // 0.04 * 2 = 0.08 < 0.09
  ASSERT_EQ(holm.size(), expected.size());
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(holm[i], expected[i], 1e-15) << i;
  // Any order; NaN stays NaN outside the family (m = 3 here).
  const std::vector<double> mixed =
      holm_adjusted(std::vector<double>{0.5, std::nan(""), 0.01, 0.3});
  EXPECT_NEAR(mixed[0], 0.6, 1e-15);
  EXPECT_TRUE(std::isnan(mixed[1]));
  EXPECT_NEAR(mixed[2], 0.03, 1e-15);
  EXPECT_NEAR(mixed[3], 0.6, 1e-15);
  EXPECT_EQ(holm_adjusted(std::vector<double>{0.6, 0.7}), (std::vector<double>{1.0, 1.0}));
  EXPECT_TRUE(holm_adjusted(std::vector<double>{}).empty());
}

}  // namespace
}  // namespace fspm
