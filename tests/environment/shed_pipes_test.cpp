// keep_shed_pipes: the radii of a grown tree keep the pipes of its shed branches (Shinozaki et
// al. 1964), each a whole number of tip pipes, without changing anything else.
#include <gtest/gtest.h>

#include <cmath>

#include "environment/growth_model.hpp"

namespace fspm::environment {
namespace {

TEST(ShedPipes, RadiiKeepWholeTipPipesOfShedBranches) {
  GrowthParams p = growth_preset("B");
  p.years = 15;
  const GrowthResult plain = grow_tree(p);
  p.keep_shed_pipes = true;
  const GrowthResult kept = grow_tree(p);
  ASSERT_GT(plain.shed, 0u);  // type B sheds by 15 years
  ASSERT_EQ(kept.tree.size(), plain.tree.size());
  const double u = p.pipe_exponent, tip = std::pow(p.tip_radius_m, u);
  std::size_t sites = 0;
  for (NodeId i = 0; i < kept.tree.size(); ++i) {
    ASSERT_EQ(kept.tree.kind(i), plain.tree.kind(i));
    EXPECT_NEAR((kept.tree.end(i) - plain.tree.end(i)).norm(), 0.0, 1e-12);
    if (kept.tree.kind(i) != OrganKind::kInternode) continue;
    EXPECT_GE(kept.tree.radius(i), plain.tree.radius(i) * (1.0 - 1e-12));
    // The excess over the living children (or the tip's own pipe) in tip pipes is a whole
    // number: the tips the shed branches had when they were shed.
    double need = 0.0;
    bool inner = false;
    for (const NodeId c : kept.tree.children(i)) {
      if (kept.tree.kind(c) != OrganKind::kInternode) continue;
      inner = true;
      need += std::pow(kept.tree.radius(c), u);
    }
    const double excess = (std::pow(kept.tree.radius(i), u) - (inner ? need : tip)) / tip;
    EXPECT_NEAR(excess, std::round(excess), 1e-6) << i;
    EXPECT_GE(std::round(excess), 0.0);
    sites += std::round(excess) > 0.0;
  }
  EXPECT_GT(sites, 0u);
  EXPECT_GT(kept.tree.radius(0), plain.tree.radius(0));
}

}  // namespace
}  // namespace fspm::environment
