// The enum name table: names both ways, the "expected a, b or c" list, the closest-name hint of an
// unknown name, the help text, and the round trip of every core enum through its name.
#include "fspm/name_table.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fspm/assignment.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/error.hpp"
#include "fspm/image_request.hpp"
#include "fspm/length_unit.hpp"
#include "fspm/statistics.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {
namespace {

enum class Fruit { kApple, kPear, kQuince };

constexpr NameTable<Fruit, 3> kFruitNames{"fruit",
                                          {{Fruit::kApple, "apple", "round"},
                                           {Fruit::kPear, "pear", "tapered"},
                                           {Fruit::kQuince, "quince", ""}}};

// A name outside the table: the message names the given name, every name, and the closest.
std::string message_of(std::string_view name, std::string_view context = {}) {
  try {
    kFruitNames.from_name(name, context);
  } catch (const ValueError& e) {
    return e.message();
  }
  return "no error";
}

TEST(NameTable, NamesBothWays) {
  static_assert(kFruitNames.name(Fruit::kPear) == "pear");
  static_assert(kFruitNames.find("quince") == Fruit::kQuince);
  static_assert(!kFruitNames.find("Pear").has_value());
  EXPECT_EQ(kFruitNames.from_name("apple"), Fruit::kApple);
  EXPECT_EQ(kFruitNames.values()[2], Fruit::kQuince);
}

TEST(NameTable, UnknownNameNamesTheClosest) {
  EXPECT_EQ(message_of("paer"),
            "unknown fruit 'paer': expected apple, pear or quince (did you "
            "mean 'pear'?)");
  EXPECT_EQ(message_of("qince", "--fruit"),
            "--fruit: unknown fruit 'qince': expected apple, pear or quince (did you mean "
            "'quince'?)");
  // Nothing close: the list alone.
  EXPECT_EQ(message_of("zzzzzzzz"), "unknown fruit 'zzzzzzzz': expected apple, pear or quince");
  EXPECT_THROW(kFruitNames.from_name(""), ValueError);
}

TEST(NameTable, ExpectedListAndHelp) {
  EXPECT_EQ(expected_names_text({"a"}), "a");
  EXPECT_EQ(expected_names_text({"a", "b"}), "a or b");
  EXPECT_EQ(expected_names_text({"a", "b", "c"}), "a, b or c");
  EXPECT_EQ(kFruitNames.expected(), "apple, pear or quince");
  EXPECT_EQ(kFruitNames.help(), "apple (round), pear (tapered), quince");
}

// Every value of every table-backed core enum survives name -> value, and names are distinct.
template <typename Enum, std::size_t N>
void expect_round_trip(const NameTable<Enum, N>& table, std::string_view (*name_of)(Enum),
                       Enum (*from_name)(std::string_view)) {
  for (const NamedValue<Enum>& e : table.entries()) {
    EXPECT_EQ(name_of(e.value), e.name);
    EXPECT_EQ(from_name(e.name), e.value) << e.name;
    EXPECT_EQ(table.find(e.name), e.value) << e.name;
  }
  EXPECT_THROW(from_name(std::string(table.entries()[0].name) + "x"), ValueError);
}

TEST(NameTable, CoreEnumsRoundTrip) {
  expect_round_trip(kEditCostKindNames, edit_cost_kind_name, edit_cost_kind_from_name);
  expect_round_trip(kAssignmentSolverNames, assignment_solver_name, assignment_solver_from_name);
  expect_round_trip(kAlternativeNames, alternative_name, alternative_from_name);
  for (View v : kViews) EXPECT_EQ(view_from_name(view_name(v)), v);
  // The enums whose tables are private to their file: every number of the enum.
  for (int k = 0; k < 4; ++k) {
    const auto kind = static_cast<OrganKind>(k);
    EXPECT_EQ(organ_kind_from_name(organ_kind_name(kind)), kind);
    const auto unit = static_cast<LengthUnit>(k);
    EXPECT_EQ(length_unit_from_name(length_unit_name(unit)), unit);
  }
  EXPECT_EQ(length_unit_name(LengthUnit::kCentimetre), "cm");
  EXPECT_EQ(organ_kind_name(OrganKind::kBud), "bud");
  EXPECT_EQ(view_name(View::kIso), "iso");
}

TEST(NameTable, MessagesOfTheCoreEnums) {
  try {
    edit_cost_kind_from_name("topologcal");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "unknown cost model 'topologcal': expected topological, absolute or standardized "
              "(did you mean 'topological'?)");
  }
  try {
    length_unit_from_name("mmm", "--length-unit");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "--length-unit: unknown unit 'mmm': expected m, dm, cm or mm (did you mean 'mm'?)");
  }
}

}  // namespace
}  // namespace fspm
