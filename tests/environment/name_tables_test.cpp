// Every light-model, tropism-pairing and sky name of the environment module both ways, and the
// message of a misspelled one.
#include <gtest/gtest.h>

#include <string>

#include "environment/daylight.hpp"
#include "environment/growth_params.hpp"
#include "environment/sky_radiation.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

template <typename Enum, std::size_t N, typename Name, typename FromName>
void expect_round_trip(const NameTable<Enum, N>& table, Name name_of, FromName from_name) {
  for (const NamedValue<Enum>& e : table.entries()) {
    EXPECT_EQ(name_of(e.value), e.name);
    EXPECT_EQ(from_name(std::string(e.name)), e.value) << e.name;
  }
  EXPECT_THROW(from_name(std::string(table.entries()[0].name) + "_"), ValueError);
}

TEST(EnvironmentNames, RoundTrip) {
  expect_round_trip(kBudLightModelNames, bud_light_model_name, bud_light_model_from_name);
  expect_round_trip(kTropismPairingNames, tropism_pairing_name, tropism_pairing_from_name);
  expect_round_trip(kClusterLightModelNames, cluster_light_model_name,
                    cluster_light_model_from_name);
  // The skies have no *_name function: the table's own names are the file's spelling.
  expect_round_trip(
      kDiffuseSplitNames, [](DiffuseSplit s) { return kDiffuseSplitNames.name(s); },
      diffuse_split_from_name);
  expect_round_trip(
      kDiffuseSkyNames, [](DiffuseSky s) { return kDiffuseSkyNames.name(s); },
      diffuse_sky_from_name);
  EXPECT_EQ(diffuse_sky_from_name("overcast"), DiffuseSky::kStandardOvercast);
  EXPECT_EQ(diffuse_split_from_name("erbs"), DiffuseSplit::kErbs);
}

TEST(EnvironmentNames, MisspelledLightModel) {
  try {
    bud_light_model_from_name("shadowgrid");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "unknown light_model 'shadowgrid': expected sky, shadow_grid or space_colonization "
              "(did you mean 'shadow_grid'?)");
  }
  try {
    cluster_light_model_from_name("canopee");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "plastic analysis: unknown light_model 'canopee': expected canopy, sky or "
              "shadow_grid (did you mean 'canopy'?)");
  }
}

// A parameter file's light_model is read through the same table and refused with its line.
TEST(EnvironmentNames, ParameterFileLightModel) {
  EXPECT_EQ(parse_growth_params("light_model = \"space_colonization\"\n").light_model,
            BudLightModel::kSpaceColonization);
  try {
    parse_growth_params("years = 3\nlight_model = \"voxels\"\n", "p.toml");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_NE(std::string(e.what()).find("light_model: expected sky, shadow_grid or "
                                         "space_colonization"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.line(), 2);
  }
  // A model of adaptation only: the registry's refusal naming the use, at the key's line.
  try {
    parse_growth_params("years = 3\nlight_model = \"canopy\"\n", "p.toml");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(), "light_model 'canopy' gives no light to buds (growth): expected " +
                               kBudLightModelNames.expected());
    EXPECT_EQ(e.line(), 2);
  }
}

}  // namespace
}  // namespace fspm::environment
