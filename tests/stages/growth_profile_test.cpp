// Growth-rate profiles of the chains (Pirk 5.3.1): closed forms of the profiles and of the
// growth times they give a hand-built tree.
#include "stages/growth_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fspm/error.hpp"
#include "stages/developmental_model.hpp"
#include "tests/stages/edge_builder.hpp"

namespace fspm::stages {
namespace {

using testing::edge;

TEST(GrowthProfile, ClosedForms) {
  const ChainProfile constant{};
  const ChainProfile squared{GrowthProfile::kAccelerating, 2.0};
  const ChainProfile logistic{GrowthProfile::kLogistic, 0.5};
  EXPECT_DOUBLE_EQ(profile_fraction(constant, 0.3), 0.3);
  EXPECT_DOUBLE_EQ(profile_fraction(squared, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(profile_time(squared, 0.25), 0.5);
  // The S-curve is symmetric about the middle of its span and complete at its end.
  EXPECT_DOUBLE_EQ(profile_fraction(logistic, 0.0), 0.0);
  EXPECT_NEAR(profile_fraction(logistic, 0.25), 0.5, 1e-12);
  EXPECT_NEAR(profile_fraction(logistic, 0.1) + profile_fraction(logistic, 0.4), 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(profile_fraction(logistic, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(profile_fraction(logistic, 0.9), 1.0);
  // 1 / (1 + e^-a(x - 1/2)) rescaled: at x = 0.1 by hand with a = 8.
  const double s = [](double x) { return 1.0 / (1.0 + std::exp(-8.0 * (x - 0.5))); }(0.1);
  const double lo = 1.0 / (1.0 + std::exp(4.0)), hi = 1.0 / (1.0 + std::exp(-4.0));
  EXPECT_NEAR(profile_fraction(logistic, 0.05), (s - lo) / (hi - lo), 1e-12);
  for (const ChainProfile& p : {constant, squared, logistic}) {
    for (double f : {0.0, 0.1, 0.5, 0.77, 1.0}) {
      EXPECT_NEAR(profile_fraction(p, profile_time(p, f)), f, 1e-12) << growth_profile_name(p.kind);
    }
  }
}

TEST(GrowthProfile, ChoiceByChain) {
  // The main chain and scaffold axes keep eq. 5.3, whatever their rate.
  EXPECT_EQ(choose_profile(1, 10.0, 10.0, 0.1, 1.0, 0.0).kind, GrowthProfile::kConstant);
  EXPECT_EQ(choose_profile(3, 3.0, 10.0, 0.1, 1.0, 0.8).kind, GrowthProfile::kConstant);
  // A short chain slow for its level: accelerating when it starts late, constant when early.
  EXPECT_EQ(choose_profile(3, 0.5, 10.0, 0.4, 1.0, 0.6).kind, GrowthProfile::kAccelerating);
  EXPECT_EQ(choose_profile(3, 0.5, 10.0, 0.4, 1.0, 0.3).kind, GrowthProfile::kConstant);
  EXPECT_EQ(choose_profile(3, 0.5, 10.0, 0.6, 1.0, 0.6).kind, GrowthProfile::kConstant);
  EXPECT_EQ(profile_choice_from_name("by_chain"), ProfileChoice::kByChain);
  EXPECT_THROW(profile_choice_from_name("linear"), ValueError);
}

// A vertical trunk of four unit edges with a lateral of two unit edges along +x at the end of
// the second. Every chain accelerating (f = tau^2): the trunk is 4 t^2 long, so its edges start
// at sqrt(k / 4) = 0, 0.5, 0.7071, 0.8660; the lateral starts with the trunk's third edge, at
// s = sqrt(0.5), and its second edge when ((t - s) / (1 - s))^2 = 1/2, at s + (1 - s) sqrt(0.5).
TEST(GrowthProfile, AcceleratingTimesByHand) {
  TreeGraph t;
  const NodeId a = edge(t, kNoNode, Eigen::Vector3d::UnitZ(), 1.0, 0.05);
  const NodeId b = edge(t, a, Eigen::Vector3d::UnitZ(), 1.0, 0.05);
  const NodeId c = edge(t, b, Eigen::Vector3d::UnitZ(), 1.0, 0.04);
  edge(t, c, Eigen::Vector3d::UnitZ(), 1.0, 0.04);
  const NodeId l = edge(t, b, Eigen::Vector3d::UnitX(), 1.0, 0.02);
  edge(t, l, Eigen::Vector3d::UnitX(), 1.0, 0.02);
  StagesParams p;
  p.profiles = ProfileChoice::kAccelerating;
  const DevelopmentalModel m(t, p);
  ASSERT_EQ(kAcceleratingExponent, 2.0);
  const std::vector<double>& s = m.start_time();
  EXPECT_NEAR(s[0], 0.0, 1e-12);
  EXPECT_NEAR(s[1], 0.5, 1e-12);
  EXPECT_NEAR(s[2], std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(s[3], std::sqrt(0.75), 1e-12);
  const double ls = std::sqrt(0.5);
  EXPECT_NEAR(s[4], ls, 1e-12);
  EXPECT_NEAR(s[5], ls + (1.0 - ls) * std::sqrt(0.5), 1e-12);
  // At t = 0.75 the trunk is 4 * 0.5625 = 2.25 long and the lateral 2 tau^2.
  const double tau = (0.75 - ls) / (1.0 - ls);
  const TreeGraph st = m.stage(0.75);
  double trunk = 0.0, lateral = 0.0;
  for (NodeId i = 0; i < st.size(); ++i) {
    if (st.kind(i) != OrganKind::kInternode) continue;
    (st.direction(i).z() > 0.5 ? trunk : lateral) += st.length(i);
  }
  EXPECT_NEAR(trunk, 2.25, 1e-12);
  EXPECT_NEAR(lateral, 2.0 * tau * tau, 1e-12);
  // Every profile ends with the given tree.
  for (ProfileChoice choice : kProfileChoices) {
    p.profiles = choice;
    const TreeGraph last = DevelopmentalModel(t, p).stage(1.0);
    ASSERT_EQ(last.size(), t.size()) << profile_choice_name(choice);
    for (NodeId i = 0; i < t.size(); ++i) EXPECT_NEAR(last.length(i), t.length(i), 1e-12);
  }
}

}  // namespace
}  // namespace fspm::stages
