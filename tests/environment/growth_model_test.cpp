#include "environment/growth_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>

#include "environment/hemisphere.hpp"
#include "environment/light_model.hpp"
#include "fspm/error.hpp"
#include "fspm/tree_summary.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::environment {
namespace {

std::size_t internodes_with(const TreeGraph& t, auto&& pred) {
  std::size_t n = 0;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kInternode && pred(i)) ++n;
  }
  return n;
}

TEST(GrowthModel, DeterministicPerSeed) {
  GrowthParams p = growth_preset("A");
  p.years = 12;
  const GrowthResult a = grow_tree(p);
  const GrowthResult b = grow_tree(p);
  EXPECT_TRUE(a.tree.identical(b.tree));
  p.seed = 2;
  const GrowthResult c = grow_tree(p);
  EXPECT_FALSE(a.tree.identical(c.tree));
}

TEST(GrowthModel, StructureIsConsistent) {
  GrowthParams p = growth_preset("A");
  p.years = 15;
  p.max_shoot_metamers = 1000;  // so that every shoot has round(v) metamers
  const GrowthResult r = grow_tree(p);
  const TreeGraph& t = r.tree;
  ASSERT_GT(r.internodes, 50u);
  EXPECT_EQ(r.grown, r.internodes + r.shed);
  EXPECT_EQ(t.size(), r.internodes + r.clusters);
  EXPECT_EQ(summarize(t).internodes, r.internodes);
  for (NodeId i = 1; i < t.size(); ++i) {
    const NodeId parent = t.parent(i);
    ASSERT_LT(parent, i);
    if (t.kind(i) != OrganKind::kInternode) continue;
    // Children start where their parent ends, are not older, and keep or raise the order.
    EXPECT_LT((t.start(i) - t.end(parent)).norm(), 1e-9);
    EXPECT_GE(t.birth_time(i), t.birth_time(parent));
    EXPECT_GE(t.order(i), t.order(parent));
    EXPECT_LE(t.order(i), t.order(parent) + 1);
    // Continuous vigour: a shoot of v internode lengths in round(v) metamers, v >= the minimum.
    EXPECT_GE(t.length(i), p.min_shoot_vigour * p.internode_length_m - 1e-12);
    EXPECT_LT(t.length(i), 1.5 * p.internode_length_m + 1e-12);
  }
  // Pipe model: r_parent^n = sum r_child^n over internode children.
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) != OrganKind::kInternode) continue;
    double sum = 0.0;
    for (NodeId c : t.children(i)) {
      if (t.kind(c) == OrganKind::kInternode) sum += std::pow(t.radius(c), p.pipe_exponent);
    }
    const double expect = sum > 0 ? std::pow(sum, 1.0 / p.pipe_exponent) : p.tip_radius_m;
    EXPECT_NEAR(t.radius(i), expect, 1e-12 * expect);
  }
  EXPECT_EQ(t.birth_time(0), 0.0);
  EXPECT_NEAR(r.height_m, summarize(t).height_m, 1e-9);
}

// Internodes carry the light their bud sensed in the last cycle, and no value (nan) where they
// had no bud: the root of a 10-year tree (its terminal bud grew on in year 1, its lateral bud
// died after lateral_bud_lifetime_years) and every internode whose main and lateral positions
// both grew into shoots before the last cycle (its buds were spent when the light was sensed).
TEST(GrowthModel, InternodesWithoutABudHaveNoLight) {
  GrowthParams p = growth_preset("A");
  p.years = 10;
  const TreeGraph t = grow_tree(p).tree;
  const auto light = t.attribute("light");
  EXPECT_TRUE(std::isnan(light[0]));
  double last_cycle = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) last_cycle = std::max(last_cycle, t.birth_time(i));
  std::vector<int> internode_children(t.size(), 0);
  for (NodeId i = 1; i < t.size(); ++i) {
    if (t.kind(i) == OrganKind::kInternode && t.birth_time(i) < last_cycle) {
      ++internode_children[t.parent(i)];
    }
  }
  std::size_t valued = 0, both_grown = 0;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) != OrganKind::kInternode) continue;
    if (internode_children[i] == 2) {
      ++both_grown;
      EXPECT_TRUE(std::isnan(light[i])) << i;
    }
    if (std::isnan(light[i])) continue;
    ++valued;
    EXPECT_GE(light[i], 0.0);
    EXPECT_LE(light[i], 1.0);
  }
  EXPECT_GT(both_grown, 10u);
  EXPECT_GT(valued, 10u);
}

// Each leaf cluster carries the light at its centre, the other final clusters shading it:
// against brute-force ray casting over the sky's directions (no shadow volumes, no closed form),
// within the error of the growth model's significance cutoff.
// Brute force of the leaf light: every direction of the sky against every other cluster, each
// attenuating by Beer-Lambert along the segment of the ray inside it, with the extinction that
// makes a diametral chord transmit the cluster's translucency (canopy_light.hpp).
double leaf_light_brute_force(const Eigen::Vector3d& p, std::span<const Sphere> spheres,
                              int directions) {
  const HemisphereDirections dirs(directions);
  double sum = 0.0, open = 0.0;
  for (int i = 0; i < dirs.size(); ++i) {
    const Eigen::Vector3d& d = dirs.direction(i);
    double depth = 0.0;
    for (std::size_t j = 0; j < spheres.size(); ++j) {
      const Eigen::Vector3d oc = spheres[j].center - p;
      const double r = spheres[j].radius_m;
      const double b = oc.dot(d), disc = b * b - oc.squaredNorm() + r * r;
      if (disc <= 0.0) continue;
      const double t0 = std::max(0.0, b - std::sqrt(disc)), t1 = b + std::sqrt(disc);
      if (t1 > t0) depth += -std::log(spheres[j].translucency) / (2 * r) * (t1 - t0);
    }
    sum += d.z() * d.z() * std::exp(-depth);
    open += d.z() * d.z();
  }
  return sum / open;
}

// Each cluster's light is the light at its centre through every cluster, its own included, as
// turbid media (record_leaf_light).
TEST(GrowthModel, ClustersCarryTheLightAtTheirCentres) {
  GrowthParams p = growth_preset("A");
  p.years = 8;
  const GrowthResult r = grow_tree(p);
  const TreeGraph& t = r.tree;
  ASSERT_GT(r.clusters, 10u);
  const auto light = t.attribute("light");
  std::size_t k = 0;
  double lo = 1.0, hi = 0.0;
  for (NodeId i = 0; i < t.size(); ++i) {
    if (t.kind(i) != OrganKind::kLeaf) continue;
    ASSERT_LT(k, r.cluster_spheres.size());
    const double expected =
        leaf_light_brute_force(t.start(i), r.cluster_spheres, p.light_directions);
    EXPECT_NEAR(light[i], expected, 0.02) << "cluster " << k;
    lo = std::min(lo, light[i]);
    hi = std::max(hi, light[i]);
    ++k;
  }
  EXPECT_EQ(k, r.clusters);
  EXPECT_GT(hi - lo, 0.05);  // the crown shades some clusters more than others
}

TEST(GrowthModel, PruningFactorSheds) {
  GrowthParams p = growth_preset("A");
  p.years = 15;
  p.pruning_factor = 0.0;
  EXPECT_EQ(grow_tree(p).shed, 0u);
  p.pruning_factor = 0.3;
  EXPECT_GT(grow_tree(p).shed, 0u);
}

TEST(GrowthModel, NeverGrowsIntoSolidObstacles) {
  Scene s;
  s.boxes.push_back(Box::from_min_max({-2, -2, 3.0}, {2, 2, 3.5}));  // a roof at 3 m
  GrowthParams p = growth_preset("B");
  p.years = 12;
  const GrowthResult r = grow_tree(p, s);
  ASSERT_GT(r.internodes, 10u);
  EXPECT_EQ(internodes_with(r.tree, [&](NodeId i) { return r.tree.end(i).z() > 3.0; }), 0u);
  EXPECT_EQ(internodes_with(r.tree, [&](NodeId i) { return r.tree.end(i).z() < 0.0; }), 0u);
}

// Pirk Table 4.2: 530 / 2 541 / 9 134 internodes at 10 / 20 / 30 years. The presets' alpha was
// fitted to the 20-year size (mean of seeds 1-8; docs/environment.md) for every light model, so 20
// years must hold to within 25 % for every type and light model; with the default light model the
// 10- and 30-year sizes follow from the growth model and hold to within 40 %.
double mean_preset_internodes(const char* preset, BudLightModel model, int years, int seeds) {
  double sum = 0.0;
  for (int seed = 1; seed <= seeds; ++seed) {
    GrowthParams p = growth_preset(preset, model);
    p.years = years;
    p.seed = static_cast<std::uint64_t>(seed);
    sum += static_cast<double>(grow_tree(p).internodes);
  }
  return sum / seeds;
}

TEST(GrowthModel, PresetSizesFollowPirkTable42) {
  const std::array<std::pair<int, double>, 3> table = {{{10, 530.0}, {20, 2541.0}, {30, 9134.0}}};
  for (const char* preset : {"A", "B", "C"}) {
    for (const auto& [years, pirk] : table) {
      const int seeds = years == 30 ? 2 : 8;
      const double tolerance = years == 20 ? 0.25 : 0.40;
      EXPECT_NEAR(mean_preset_internodes(preset, BudLightModel::kShadowGrid, years, seeds) / pirk,
                  1.0, tolerance)
          << preset << ", " << years << " years";
    }
  }
}

TEST(GrowthModel, PresetAlphaIsFittedForEveryLightModel) {
  for (BudLightModel model : {BudLightModel::kSky, BudLightModel::kSpaceColonization}) {
    for (const char* preset : {"A", "B", "C"}) {
      EXPECT_NEAR(mean_preset_internodes(preset, model, 20, 8) / 2541.0, 1.0, 0.25)
          << preset << ", " << bud_light_model_name(model);
    }
  }
}

TEST(GrowthModel, PresetsDifferInTropisms) {
  EXPECT_DOUBLE_EQ(growth_preset("A").phototropism, 0.25);
  EXPECT_DOUBLE_EQ(growth_preset("A").gravitropism, 0.12);
  EXPECT_DOUBLE_EQ(growth_preset("B").phototropism, 0.45);
  EXPECT_DOUBLE_EQ(growth_preset("B").gravitropism, 0.44);
  EXPECT_DOUBLE_EQ(growth_preset("C").phototropism, 0.03);
  EXPECT_DOUBLE_EQ(growth_preset("C").gravitropism, 0.23);
  EXPECT_GT(growth_preset("C").years, growth_preset("A").years);
  EXPECT_LT(growth_preset("C").pruning_factor, growth_preset("A").pruning_factor);
  EXPECT_THROW(growth_preset("D"), ValueError);
}

// Apical control 0.9 on type B sends the vigour up the main axes: the tree is 160 m tall after 10
// years (1 237 internodes and 326 m after 12), where a real tree stops near 116 m. Growth stops
// at max_height_m with a message naming the limit and the parameters, not the light model's.
TEST(GrowthLimits, ExplodingTreeStopsAtMaxHeightNamingTheParameters) {
  GrowthParams p = growth_preset("B");
  p.apical_control = 0.9;
  p.years = 30;
  try {
    grow_tree(p);
    FAIL() << "no GrowthLimitError";
  } catch (const GrowthLimitError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("growth stopped after year "), std::string::npos) << m;
    EXPECT_NE(m.find(" of 30: "), std::string::npos) << m;
    EXPECT_NE(m.find("above max_height_m = 150 m"), std::string::npos) << m;
    EXPECT_NE(m.find("apical_control 0.9"), std::string::npos) << m;
    EXPECT_NE(m.find("--max-internodes"), std::string::npos) << m;
    EXPECT_EQ(m.find("voxel"), std::string::npos) << m;
    EXPECT_LE(m.size(), kMaxErrorMessageLength - 40) << "room for the command line's prefix";
  }
  // Without the height limit the same tree runs into the internode limit instead.
  p.max_height_m = std::numeric_limits<double>::infinity();
  p.max_internodes = 500;
  p.light_model = BudLightModel::kSky;  // no grid to outgrow
  try {
    grow_tree(p);
    FAIL() << "no GrowthLimitError";
  } catch (const GrowthLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("above max_internodes = 500"), std::string::npos)
        << e.what();
  }
}

// The limits stop only what exceeds them: a preset tree far below both grows as before.
TEST(GrowthLimits, TreesBelowTheLimitsAreUntouched) {
  GrowthParams p = growth_preset("A");
  p.years = 10;
  const GrowthResult free = grow_tree(p);
  ASSERT_GT(free.internodes, 50u);
  p.max_internodes = free.internodes;  // the final tree is checked too: equal passes
  EXPECT_TRUE(grow_tree(p).tree.identical(free.tree));
  p.max_internodes = free.internodes - 1;
  EXPECT_THROW(grow_tree(p), GrowthLimitError);
  p.max_internodes = 1'000'000;
  p.max_height_m = free.height_m * 0.5;
  EXPECT_THROW(grow_tree(p), GrowthLimitError);
  EXPECT_THROW(parse_growth_params("max_internodes = 0\n", "p.toml"), ValueError);
  EXPECT_EQ(parse_growth_params("max_internodes = 7\n", "p.toml").max_internodes, 7u);
}

TEST(GrowthParams, TomlOverridesPresetAndRejectsBadInput) {
  const GrowthParams p = parse_growth_params("preset = \"B\"\nyears = 7\nalpha = 2.5\n", "p.toml");
  EXPECT_EQ(p.years, 7);
  EXPECT_DOUBLE_EQ(p.alpha, 2.5);
  EXPECT_DOUBLE_EQ(p.phototropism, 0.45);
  try {
    parse_growth_params("years = 5\nalpah = 2\n", "p.toml");
    FAIL();
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.file(), "p.toml");
    EXPECT_NE(e.message().find("unknown key 'alpah' (did you mean 'alpha'?)"), std::string::npos)
        << e.what();
  }
  try {
    parse_growth_params("apical_control = 1.5\n", "p.toml");
    FAIL();
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("[0, 1]"), std::string::npos);
  }
  EXPECT_THROW(parse_growth_params("phototropism = 0.6\ngravitropism = 0.5\n"), ValueError);
  EXPECT_THROW(parse_growth_params("years = [\n"), ParseError);
}

// With the sky light model a tree beside a wall is one-sided: the wall (x = 2.5 m, 6 m high,
// running along y) hides much of the sky from the +x side and stops growth there, so most of the
// crown grows on the -x side (not for type C, whose phototropism of 0.03 cannot lean it; for C
// only the wall stopping growth is checked).
TEST(GrowthModel, TreeBesideWallIsOneSided) {
  Scene wall;
  wall.boxes.push_back(Box::wall({2.5, -20}, {2.5, 20}, 0.0, 6.0, 0.2));
  for (const char* preset : {"A", "B", "C"}) {
    GrowthParams p = growth_preset(preset, BudLightModel::kSky);
    p.years = 15;
    const GrowthResult open = grow_tree(p);
    const GrowthResult beside = grow_tree(p, wall);
    auto side = [](const GrowthResult& r, bool east) {
      return internodes_with(r.tree, [&](NodeId i) { return (r.tree.end(i).x() > 0.0) == east; });
    };
    const std::size_t open_w = side(open, false), open_e = side(open, true);
    const std::size_t wall_w = side(beside, false), wall_e = side(beside, true);
    std::printf("preset %s: open west %zu east %zu | wall west %zu east %zu\n", preset, open_w,
                open_e, wall_w, wall_e);
    // Open-grown trees are roughly balanced, trees beside the wall are not.
    EXPECT_LT(std::abs(static_cast<double>(open_w) - open_e), 0.5 * (open_w + open_e));
    if (preset[0] != 'C') {
      EXPECT_GT(static_cast<double>(wall_w), 1.5 * wall_e) << preset;
    }
    EXPECT_EQ(internodes_with(beside.tree, [&](NodeId i) { return beside.tree.end(i).x() > 2.4; }),
              0u);
  }
}

}  // namespace
}  // namespace fspm::environment

namespace fspm::environment {
namespace {

struct TreeSize {
  double internodes = 0, height_m = 0, crown_x_m = 0;
  double internodes_before_x = 0;  // internodes whose end lies at x < the given bound
};

// Mean size and crown centre (mean x of the leaf clusters) over seeds 1..seeds.
TreeSize mean_size(GrowthParams p, const Scene& scene, int seeds, double x_bound = 1e300) {
  TreeSize s;
  for (int seed = 1; seed <= seeds; ++seed) {
    p.seed = static_cast<std::uint64_t>(seed);
    const GrowthResult r = grow_tree(p, scene);
    double x = 0.0;
    for (const Sphere& c : r.cluster_spheres) x += c.center.x() / r.cluster_spheres.size();
    const auto before =
        internodes_with(r.tree, [&](NodeId i) { return r.tree.end(i).x() < x_bound; });
    s.internodes += static_cast<double>(r.internodes) / seeds;
    s.internodes_before_x += static_cast<double>(before) / seeds;
    s.height_m += r.height_m / seeds;
    s.crown_x_m += x / seeds;
  }
  return s;
}

// Botanically, a tree 2 m from a 4 m wall keeps most of its size and leans and spreads away from
// the wall. With the default light model (local shadow propagation), trees of every type grown
// 30 years beside the wall of the adapted-versus-grown experiment keep their height, their crowns
// lie on the far side of the trunk, and they keep at least 70 % of the open trees' internodes in
// front of the wall's face. Types A and B also keep 70 % of all the open trees' internodes; the
// wide crown of type C puts 14-25 % of its internodes beyond the wall's face in the open, and its
// phototropism of 0.03 cannot turn that growth away (docs/environment.md).
TEST(GrowthModel, TreeBesideWallKeepsItsSizeAndLeansAway) {
  Scene wall;
  wall.boxes.push_back(Box::wall({2.0, -20}, {2.0, 20}, 0.0, 4.0, 0.2));
  const double face_x_m = 1.9;
  for (const char* preset : {"A", "B", "C"}) {
    GrowthParams p = growth_preset(preset);
    p.years = 30;
    const TreeSize open = mean_size(p, Scene{}, 6, face_x_m);
    const TreeSize beside = mean_size(p, wall, 6, face_x_m);
    std::printf(
        "preset %s: open %.0f internodes (%.0f before the face) %.2f m crown x %.2f m | "
        "wall %.0f %.2f m %.2f m\n",
        preset, open.internodes, open.internodes_before_x, open.height_m, open.crown_x_m,
        beside.internodes, beside.height_m, beside.crown_x_m);
    EXPECT_GE(beside.internodes, 0.7 * open.internodes_before_x) << preset;
    if (preset[0] != 'C') {
      EXPECT_GE(beside.internodes, 0.7 * open.internodes) << preset;
    }
    EXPECT_GE(beside.height_m, 0.9 * open.height_m) << preset;
    EXPECT_LT(beside.crown_x_m, 0.0) << preset;
    EXPECT_LT(beside.crown_x_m, open.crown_x_m - 0.3) << preset;
  }
}

// The local light models answer a wall by growing away from it. (The sky model answers a wall
// this close mostly by not growing: docs/environment.md.)
TEST(GrowthModel, LocalLightModelsGrowAwayFromAWall) {
  Scene wall;
  wall.boxes.push_back(Box::wall({1.0, -20}, {1.0, 20}, 0.0, 6.0, 0.2));
  for (BudLightModel m : {BudLightModel::kShadowGrid, BudLightModel::kSpaceColonization}) {
    GrowthParams p = growth_preset("A", m);
    p.years = 12;
    const TreeSize open = mean_size(p, Scene{}, 2);
    const TreeSize beside = mean_size(p, wall, 2);
    std::printf("%s: open %.0f internodes crown x %.2f m | wall %.0f, %.2f m\n",
                bud_light_model_name(m).data(), open.internodes, open.crown_x_m, beside.internodes,
                beside.crown_x_m);
    EXPECT_LT(beside.crown_x_m, open.crown_x_m - 0.1) << bud_light_model_name(m);
    EXPECT_GT(beside.internodes, 0) << bud_light_model_name(m);
  }
}

TEST(GrowthParams, LightModelAndPresetTropismsFromToml) {
  const GrowthParams p = parse_growth_params(
      "preset = \"B\"\nlight_model = \"sky\"\npreset_tropisms = \"appendix\"\n");
  EXPECT_EQ(p.light_model, BudLightModel::kSky);
  EXPECT_DOUBLE_EQ(p.alpha, growth_preset("B", BudLightModel::kSky).alpha);
  EXPECT_DOUBLE_EQ(p.gravitropism, 0.03);
  EXPECT_DOUBLE_EQ(growth_preset("C", BudLightModel::kSky, TropismPairing::kAppendix).phototropism,
                   0.44);
  EXPECT_EQ(parse_growth_params("light_model = \"space_colonization\"\n").light_model,
            BudLightModel::kSpaceColonization);
  try {
    parse_growth_params("years = 3\nlight_model = \"voxels\"\n", "p.toml");
    FAIL() << "an unknown light model was accepted";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.line(), 2);
  }
  EXPECT_THROW(parse_growth_params("preset_tropisms = \"text\"\n"), ValueError);
  EXPECT_THROW(parse_growth_params("shadow_b = 1.0\n"), ValueError);
  EXPECT_THROW(parse_growth_params("sky_light_fraction = 1.5\n"), ValueError);
}

// Continuous vigour: a bud's shoot length follows its vigour, so a darker sky gives smaller trees
// on average (the measured table of size against light is in docs/environment.md), and no light
// gives no growth.
TEST(GrowthModel, LessLightNeverGivesLargerTrees) {
  GrowthParams p = growth_preset("A");
  p.years = 15;
  double previous = 1e300;
  for (double f : {1.0, 0.6, 0.3}) {
    p.sky_light_fraction = f;
    const double n = mean_size(p, Scene{}, 3).internodes;
    EXPECT_LT(n, previous) << f;
    previous = n;
  }
  p.sky_light_fraction = 0.0;
  EXPECT_EQ(grow_tree(p).internodes, 1u);
}

// Each cycle checks the tree it is about to have against the memory limit: at 1 MiB a 10-year
// tree of type A (about 380 metamers, some 150 kB) grows, a 30-year one (about 11 000 metamers,
// several MB) stops with MemoryLimitError before it allocates them. The sky light model keeps no
// grid, so the metamers are all that is counted.
TEST(GrowthModel, MemoryLimitStopsAGrowingTreeInBytes) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  GrowthParams p = growth_preset("A", BudLightModel::kSky);
  p.years = 10;
  EXPECT_NO_THROW(grow_tree(p));
  p.years = 30;
  try {
    grow_tree(p);
    FAIL() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("metamers"), std::string::npos) << e.what();
  }
}

// The shadow grid of the default light model is counted too: the 10-year tree's grid (about
// 21 000 voxels of 37 bytes, with half again of room) does not fit in 1 MiB.
TEST(GrowthModel, MemoryLimitCountsTheShadowGrid) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  GrowthParams p = growth_preset("A");
  p.years = 10;
  try {
    grow_tree(p);
    FAIL() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_NE(std::string(e.what()).find("shadow grid"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fspm::environment
