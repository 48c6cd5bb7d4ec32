#include "environment/light_profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "fspm/attribute_names.hpp"

namespace fspm::environment {
namespace {

// A trunk from z = 1 to 5 with leaves at known heights and lights: the layers' means are the
// hand-computed ones, heights above the base, empty layers and leaves without light left out.
TEST(LightProfile, LayersOfLeafLightByHeight) {
  TreeGraph t;
  NodeData trunk;
  trunk.start = {0, 0, 1};
  trunk.end = {0, 0, 5};
  const NodeId root = t.add_node(kNoNode, trunk);
  const double z[] = {1.0, 1.5, 3.0, 5.0, 4.9, 2.0};
  const double l[] = {0.2, 0.4, 0.5, 0.9, 0.7, std::nan("")};
  for (int k = 0; k < 6; ++k) {
    NodeData leaf;
    leaf.kind = OrganKind::kLeaf;
    leaf.start = leaf.end = {0.3, 0, z[k]};
    leaf.radius = 0.3;
    t.add_node(root, leaf);
  }
  t.add_attribute(kLightAttribute, std::nan(""));
  auto light = t.attribute(kLightAttribute);
  for (int k = 0; k < 6; ++k) light[static_cast<std::size_t>(k) + 1] = l[k];
  // Leaves from z = 1 to 5 in 4 layers of 1 m: [1, 2) holds 0.2 and 0.4, [3, 4) 0.5,
  // [4, 5] 0.9 and 0.7; [2, 3) is empty (its leaf has no light).
  const std::vector<LightLayer> p = leaf_light_profile(t, 4);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_NEAR(p[0].height_m, 0.5, 1e-12);
  EXPECT_NEAR(p[0].mean_light, 0.3, 1e-12);
  EXPECT_EQ(p[0].clusters, 2);
  EXPECT_NEAR(p[1].height_m, 2.5, 1e-12);
  EXPECT_NEAR(p[1].mean_light, 0.5, 1e-12);
  EXPECT_NEAR(p[2].height_m, 3.5, 1e-12);
  EXPECT_NEAR(p[2].mean_light, 0.8, 1e-12);
  TreeGraph bare;
  bare.add_node(kNoNode, trunk);
  EXPECT_TRUE(leaf_light_profile(bare).empty());
}

}  // namespace
}  // namespace fspm::environment
