#include "environment/light_environment.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"

namespace fspm::environment {
namespace {

TEST(LightEnvironment, AnswersCommunicationModules) {
  Scene s;
  s.spheres.push_back({{0, 0, 3}, 1.0, 0.0, false});
  s.boxes.push_back(Box::from_min_max({500, -1, 0}, {501, 1, 2}));  // beyond its shadow volume
  LightEnvironment env(s);
  lsystem::OpenEnvironment& open = env;
  std::vector<lsystem::EnvironmentQuery> q(3);
  q[0].position = {0, 0, 0};      // under an opaque sphere: cos^3(alpha), sin alpha = 1/3
  q[1].position = {200, 200, 0};  // open sky, beyond every shadow volume
  q[2].position = {500.5, 0, 1};  // inside the box
  q[1].parameters = {7.0};        // old values are replaced
  open.respond(q);
  ASSERT_EQ(q[0].parameters.size(), 5u);
  EXPECT_NEAR(q[0].parameters[0], std::pow(std::sqrt(8.0 / 9.0), 3), 1e-12);
  EXPECT_NEAR(q[0].parameters[3], 1.0, 1e-12);
  EXPECT_EQ(q[0].parameters[4], 0.0);
  EXPECT_EQ(q[1].parameters[0], 1.0);
  EXPECT_EQ(q[2].parameters[4], 1.0);
  EXPECT_EQ(q[2].parameters[0], 0.0);  // inside an opaque box every ray is blocked
}

}  // namespace
}  // namespace fspm::environment

namespace fspm::environment {
namespace {

// An open L-system whose apex carries ?E grows under an opaque sphere (radius 1.5, centre at
// height 6): after three steps the apex is at height 3, where the closed form gives
// light = cos^3(alpha) with sin(alpha) = 1.5 / 3.
TEST(LightEnvironment, DrivesAnOpenLsystem) {
  const lsystem::LSystem sys = lsystem::parse_lsystem("Axiom: A?E(0,0,0,0,0)\nA --> F(1)A\n");
  Scene s;
  s.spheres.push_back({{0, 0, 6}, 1.5, 0.0, false});
  LightEnvironment env(s);
  lsystem::DeriveOptions o;
  o.steps = 3;
  o.environment = &env;
  const lsystem::ModuleString str = lsystem::derive(sys, o);
  const int e = sys.symbols.find("?E");
  ASSERT_GE(e, 0);
  bool found = false;
  for (std::size_t i = 0; i < str.size(); ++i) {
    if (static_cast<int>(str.symbol(i)) != e) continue;
    found = true;
    const auto p = str.parameters(i);
    ASSERT_EQ(p.size(), 5u);
    EXPECT_NEAR(p[0], std::pow(std::sqrt(0.75), 3), 1e-12);
    EXPECT_NEAR(p[3], 1.0, 1e-12);
    EXPECT_EQ(p[4], 0.0);
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace fspm::environment
