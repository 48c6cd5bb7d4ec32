#include "greenlab/plant_params.hpp"

#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

const char* kValid = R"([plant]
cycles = 10
seed = 1
[[age]]
index = 1
duration = 5
next_age = 2
terminal = "flower"
branching_delay = 1
units = [
  { count = 2 },
  { count = 1, axillary = [ { age = 2, count = 2 } ] },
]
branching_probability = 1.0
growth_probability = 1.0
survival_probability = 1.0
leaf_life_span = 1
axis_life_span = 0
branching_angle = 60.0
phyllotaxy = 147.5
internode_length = 1.0
[[age]]
index = 2
duration = 3
next_age = 0
units = [ { count = 1 } ]
)";

// Replaces the first occurrence of `from` in the valid description.
std::string with(const std::string& from, const std::string& to) {
  std::string s = kValid;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  s.replace(at, from.size(), to);
  return s;
}

// The error message and line of parsing `text`.
std::pair<std::string, int> error_of(const std::string& text) {
  try {
    parse_plant_params(text, "plant.toml");
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "plant.toml");
    return {e.message(), e.line()};
  }
  ADD_FAILURE() << "no error";
  return {"", 0};
}

TEST(PlantParams, ParsesAValidDescription) {
  const PlantParams p = parse_plant_params(kValid, "plant.toml");
  EXPECT_EQ(p.cycles, 10);
  ASSERT_EQ(p.ages.size(), 2u);
  const AgeParams& a = p.age(1);
  EXPECT_EQ(a.duration, 5);
  EXPECT_EQ(a.next_age, 2);
  EXPECT_EQ(a.terminal, Terminal::kFlower);
  ASSERT_EQ(a.units.size(), 2u);
  EXPECT_EQ(a.units[0].count, 2);
  ASSERT_EQ(a.units[1].axillary.size(), 1u);
  EXPECT_EQ(a.units[1].axillary[0].age, 2);
  EXPECT_EQ(a.units[1].axillary[0].count, 2);
  EXPECT_DOUBLE_EQ(a.geometry.phyllotaxy_deg, 147.5);
  EXPECT_FALSE(p.stochastic());
}

TEST(PlantParams, MissingKeyNamesKeyAndLine) {
  const auto [msg, line] = error_of(with("duration = 5\n", ""));
  EXPECT_NE(msg.find("missing key 'age[0].duration'"), std::string::npos) << msg;
  EXPECT_EQ(line, 4);  // the [[age]] header
}

TEST(PlantParams, UnknownKeyNamesKeyAndLine) {
  const auto [msg, line] = error_of(with("phyllotaxy = 147.5", "phylotaxy = 147.5"));
  EXPECT_NE(msg.find("unknown key 'age[0].phylotaxy' (did you mean 'phyllotaxy'?)"),
            std::string::npos)
      << msg;
  EXPECT_EQ(line, 20);
  const auto [msg2, line2] = error_of(with("{ count = 2 },", "{ count = 2, colour = 1 },"));
  EXPECT_NE(msg2.find("age[0].units[0].colour"), std::string::npos) << msg2;
  EXPECT_EQ(line2, 11);
}

TEST(PlantParams, TransitionToLowerAgeIsRejected) {
  std::string text = kValid;
  text.replace(text.rfind("next_age = 0"), 12, "next_age = 1");
  const auto [msg, line] = error_of(text);
  EXPECT_NE(msg.find("age[1].next_age"), std::string::npos) << msg;
  EXPECT_NE(msg.find("higher physiological age"), std::string::npos) << msg;
  EXPECT_EQ(line, 25);
  // A lateral bud of a lower age than its axis.
  std::string bud = kValid;
  bud.replace(bud.rfind("units = [ { count = 1 } ]"), 25,
              "units = [ { count = 1, axillary = [ { age = 1 } ] } ]");
  const auto [msg2, line2] = error_of(bud);
  EXPECT_NE(msg2.find("age[1].units[0].axillary[0].age"), std::string::npos) << msg2;
  EXPECT_EQ(line2, 26);
}

TEST(PlantParams, NegativeCountIsRejected) {
  const auto [msg, line] = error_of(with("{ count = 2 },", "{ count = -2 },"));
  EXPECT_NE(msg.find("age[0].units[0].count"), std::string::npos) << msg;
  EXPECT_NE(msg.find("-2"), std::string::npos) << msg;
  EXPECT_EQ(line, 11);
}

TEST(PlantParams, ProbabilityOutsideUnitIntervalIsRejected) {
  const auto [msg, line] = error_of(with("growth_probability = 1.0", "growth_probability = 1.5"));
  EXPECT_NE(msg.find("age[0].growth_probability"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[0, 1]"), std::string::npos) << msg;
  EXPECT_EQ(line, 15);
  const auto [msg2, line2] =
      error_of(with("branching_probability = 1.0", "branching_probability = -0.1"));
  EXPECT_NE(msg2.find("branching_probability"), std::string::npos) << msg2;
  EXPECT_EQ(line2, 14);
}

TEST(PlantParams, SyntaxErrorHasLine) {
  const auto [msg, line] = error_of(with("cycles = 10", "cycles = = 10"));
  EXPECT_EQ(line, 2);
}

TEST(PlantParams, ExamplesParse) {
  for (const char* name :
       {"jaeger_figure1.toml", "leeuwenberg.toml", "rauh.toml", "massart.toml"}) {
    EXPECT_NO_THROW(testing::example(name)) << name;
  }
}

TEST(PlantParams, NamedParameters) {
  PlantParams p = parse_plant_params(kValid);
  set_parameter(p, "age.2.leaf_sink", 3.5);
  EXPECT_DOUBLE_EQ(p.age(2).functional.leaf_sink, 3.5);
  EXPECT_DOUBLE_EQ(get_parameter(p, "age.2.leaf_sink"), 3.5);
  EXPECT_THROW(get_parameter(p, "age.3.leaf_sink"), ValueError);
  EXPECT_THROW(get_parameter(p, "colour"), ValueError);
}

}  // namespace
}  // namespace fspm::greenlab
