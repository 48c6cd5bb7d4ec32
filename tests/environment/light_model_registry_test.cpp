// The one registry of light models (environment/light_model_registry.hpp): the names of each use
// are the rows with its hook, a model asked for a use it has no hook for is refused by name, and
// every registered model does its job for each use it has (so a new row is tested here too).
#include "environment/light_model_registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "environment/growth_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::environment {
namespace {

template <std::size_t N>
std::vector<std::string_view> names_of(const NameTable<LightModelKind, N>& table) {
  return table.names();
}

TEST(LightModelRegistry, TheNamesOfEachUseAreTheRowsWithItsHook) {
  std::vector<std::string_view> buds, clusters;
  for (const LightModelEntry& e : kLightModels) {
    EXPECT_EQ(kLightModelNames.find(e.name), e.kind) << e.name;
    EXPECT_EQ(light_model_name(e.kind), e.name);
    EXPECT_EQ(kBudLightModelNames.find(e.name).has_value(), lights_buds(e)) << e.name;
    EXPECT_EQ(kClusterLightModelNames.find(e.name).has_value(), lights_clusters(e)) << e.name;
    if (lights_buds(e)) buds.push_back(e.name);
    if (lights_clusters(e)) clusters.push_back(e.name);
  }
  // In the rows' order, which is that of the help and of the messages.
  EXPECT_EQ(names_of(kBudLightModelNames), buds);
  EXPECT_EQ(names_of(kClusterLightModelNames), clusters);
}

TEST(LightModelRegistry, AModelAskedForAUseItLacksIsRefusedByName) {
  try {
    bud_light_model_from_name("canopy");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    // The models of growth follow (EnvironmentNames.MisspelledLightModel spells them out).
    EXPECT_EQ(e.message(), "light_model 'canopy' gives no light to buds (growth): expected " +
                               kBudLightModelNames.expected());
  }
  try {
    cluster_light_model_from_name("space_colonization");
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.message(),
              "plastic analysis: light_model 'space_colonization' gives no light to leaf "
              "clusters (plastic adaptation): expected " +
                  kClusterLightModelNames.expected());
  }
  GrowthParams growth;
  growth.light_model = LightModelKind::kCanopy;
  growth.years = 1;
  for (const auto& call :
       {std::function<void()>([&] { growth.validate(); }),
        std::function<void()>([&] { grow_tree(growth); }),
        std::function<void()>([] { growth_preset("A", LightModelKind::kCanopy); })}) {
    try {
      call();
      ADD_FAILURE() << "no error";
    } catch (const ValueError& e) {
      EXPECT_NE(e.message().find("'canopy' gives no light to buds"), std::string::npos)
          << e.message();
    }
  }
  TreeGraph tree;
  tree.add_node(kNoNode, {});
  AnalysisParams analysis;
  analysis.light_model = LightModelKind::kSpaceColonization;
  try {
    analyze_tree(tree, analysis);
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_NE(e.message().find("'space_colonization' gives no light to leaf clusters"),
              std::string::npos)
        << e.message();
  }
}

// Every model with a bud light grows a tree whose buds sensed light in [0, 1].
TEST(LightModelRegistry, EveryBudLightGrowsATree) {
  for (const LightModelEntry& e : kLightModels) {
    if (!lights_buds(e)) continue;
    GrowthParams p = growth_preset("A", e.kind);
    p.years = 6;
    const GrowthResult r = grow_tree(p);
    EXPECT_GT(r.internodes, 20u) << e.name;
    const auto light = r.tree.attribute("light");
    std::size_t lit = 0;
    for (NodeId i = 0; i < r.tree.size(); ++i) {
      if (std::isnan(light[i])) continue;
      ++lit;
      EXPECT_GE(light[i], 0.0) << e.name;
      EXPECT_LE(light[i], 1.0 + 1e-9) << e.name;
    }
    EXPECT_GT(lit, 0u) << e.name;
  }
}

// Every model with a cluster light gives the analysed clusters light in [0, 1] and adapts a tree
// to the open scene it was analysed in without moving or pruning anything (the adaptation's
// bending is relative to the analysis' light).
TEST(LightModelRegistry, EveryClusterLightLeavesAnUnchangedSceneUnchanged) {
  const TreeGraph tree = read_tree_file(FSPM_SOURCE_DIR "/examples/trees/open_a12.treeb");
  for (const LightModelEntry& e : kLightModels) {
    if (!lights_clusters(e)) continue;
    AnalysisParams params;
    params.light_model = e.kind;
    const TreeAnalysis a = analyze_tree(tree, params);
    ASSERT_EQ(a.cluster_light.size(), a.clusters.size()) << e.name;
    ASSERT_GT(a.clusters.size(), 10u) << e.name;
    for (const double light : a.cluster_light) {
      EXPECT_GE(light, 0.0) << e.name;
      EXPECT_LE(light, 1.0 + 1e-9) << e.name;
    }
    const AdaptationResult r = adapt_tree(tree, a, Scene{});
    EXPECT_EQ(r.pruned_nodes, 0u) << e.name;
    EXPECT_EQ(r.bent_segments, 0u) << e.name;
    EXPECT_LT(r.mean_tip_displacement_m, 1e-9) << e.name;
  }
}

}  // namespace
}  // namespace fspm::environment
