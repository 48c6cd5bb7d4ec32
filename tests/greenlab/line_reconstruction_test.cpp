// reconstruct_lines builds axes without orientation-dependent effects once and copies them by
// rigid transforms; the oracle is reconstruct(), which walks every axis of the plant. Both must
// give the same records in the same order, equal up to single precision.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/error.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

using testing::example;

void expect_same_plant(const TreeGraph& tree, const LineTree& lines, const std::string& what) {
  ASSERT_EQ(lines.size(), tree.size()) << what;
  // Single precision: positions to a few ulps of the plant's extent.
  double extent = 1.0;
  for (NodeId n = 0; n < tree.size(); ++n) extent = std::max(extent, tree.start(n).norm());
  const double tol = 4e-6 * extent;
  std::size_t bad = 0;
  for (NodeId n = 0; n < tree.size() && bad < 5; ++n) {
    const bool same = lines.parents()[n] == tree.parent(n) && lines.kinds()[n] == tree.kind(n) &&
                      lines.physiological_ages()[n] == tree.physiological_age(n) &&
                      lines.orders()[n] == tree.order(n) &&
                      (lines.starts()[n].cast<double>() - tree.start(n)).norm() <= tol &&
                      (lines.end(n).cast<double>() - tree.end(n)).norm() <= tol &&
                      (lines.directions()[n].cast<double>() - tree.direction(n)).norm() <= 1e-5 &&
                      lines.lengths()[n] == static_cast<float>(tree.length(n)) &&
                      lines.radii()[n] == static_cast<float>(tree.radius(n)) &&
                      lines.birth_times()[n] == static_cast<float>(tree.birth_time(n));
    if (!same) {
      ++bad;
      ADD_FAILURE() << what << ": record " << n << " differs (parent " << lines.parents()[n]
                    << " vs " << tree.parent(n) << ", start " << lines.starts()[n].transpose()
                    << " vs " << tree.start(n).transpose() << ")";
    }
  }
  EXPECT_EQ(lines.has_dead(), tree.has_attribute("dead")) << what;
  if (lines.has_dead() && tree.has_attribute("dead")) {
    for (NodeId n = 0; n < tree.size(); ++n) {
      ASSERT_EQ(lines.dead()[n] != 0, tree.attribute("dead")[n] != 0.0) << what << " " << n;
    }
  }
}

void check_plant(const PlantParams& params, const std::string& name) {
  const CompressedTreeGraph g = simulate_compressed(params);
  for (const double age : {g.final_age, std::floor(0.6 * g.final_age), 1.0}) {
    const std::string what = name + " at age " + std::to_string(age);
    ReconstructionStats tree_stats, line_stats;
    const TreeGraph tree = reconstruct(g, {.age = age}, &tree_stats);
    const LineTree lines = reconstruct_lines(g, {.age = age}, &line_stats);
    expect_same_plant(tree, lines, what);
    EXPECT_EQ(line_stats.metamers, tree_stats.metamers) << what;
    EXPECT_EQ(line_stats.leaves, tree_stats.leaves) << what;
    EXPECT_EQ(line_stats.flowers, tree_stats.flowers) << what;
    EXPECT_EQ(line_stats.pruned_axes, tree_stats.pruned_axes) << what;
    EXPECT_EQ(line_stats.age, tree_stats.age) << what;
  }
}

TEST(LineReconstruction, SameRecordsAsTheExplicitTreeForEveryExample) {
  // Leeuwenberg has no orientation-dependent age once straightening is off (every lateral is a
  // copied prototype), Massart is plagiotropic and Rauh straightens (walked), Table 1 mixes both.
  for (const char* name :
       {"leeuwenberg.toml", "rauh.toml", "massart.toml", "jaeger_figure1.toml", "gl1_plant.toml"}) {
    check_plant(example(name), name);
  }
  PlantParams free = example("leeuwenberg.toml");
  for (auto& a : free.ages) a.geometry.straightening = 0.0;
  check_plant(free, "leeuwenberg without straightening");
}

TEST(LineReconstruction, Table1TreeMixesWalkedAndCopiedAxes) {
  // Straightening on the age-2 branches (walked one by one), none above (copied prototypes); an
  // early age keeps the test small.
  const CompressedTreeGraph g = simulate_compressed(example("table1_tree.toml"));
  ReconstructionStats tree_stats, line_stats;
  const TreeGraph tree = reconstruct(g, {.age = 18.0}, &tree_stats);
  const LineTree lines = reconstruct_lines(g, {.age = 18.0}, &line_stats);
  ASSERT_GT(tree.size(), 10000u);
  expect_same_plant(tree, lines, "table 1 tree at age 18");
  EXPECT_EQ(line_stats.components(), tree_stats.components());
}

// The placed prototypes are copied on every core: on one thread, and four at a time inside an
// enclosing parallel loop (whose tasks a waiting thread must not take up: they would reuse its
// lists), the lines are still the explicit tree's, record for record.
TEST(LineReconstruction, SameRecordsOnAnyNumberOfThreads) {
  const CompressedTreeGraph g = simulate_compressed(example("table1_tree.toml"));
  const ReconstructionOptions options{.age = 22.0};
  const TreeGraph tree = reconstruct(g, options);
  ASSERT_GT(tree.size(), 50000u);
  tbb::task_arena one_thread(1);
  LineTree lines;
  one_thread.execute([&] { lines = reconstruct_lines(g, options); });
  expect_same_plant(tree, lines, "table 1 tree on one thread");
  std::vector<LineTree> nested(4);
  tbb::parallel_for(std::size_t{0}, nested.size(),
                    [&](std::size_t k) { nested[k] = reconstruct_lines(g, options); });
  for (std::size_t k = 0; k < nested.size(); ++k) {
    expect_same_plant(tree, nested[k], "table 1 tree, nested run " + std::to_string(k));
  }
}

TEST(LineReconstruction, SelfPruningWithAPruningPeriodKeepsTheDeadFlags) {
  PlantParams p = example("leeuwenberg.toml");
  for (auto& a : p.ages) {
    a.geometry.leaf_life_span = 2;
    a.geometry.pruning_period = 1;
    if (a.index > 1) a.geometry.axis_life_span = 3;
  }
  check_plant(p, "pruned leeuwenberg");
}

TEST(LineReconstruction, StochasticPlantsToo) {
  const std::string text = testing::two_age_plant(12, 2, 2, 0.7, 0.8, 0.95);
  for (int seed = 1; seed <= 3; ++seed) {
    PlantParams p = parse_plant_params(text);
    p.seed = static_cast<std::uint64_t>(seed);
    check_plant(p, "GL2 seed " + std::to_string(seed));
  }
}

TEST(LineReconstruction, ReusedColumnsGiveTheSameResult) {
  const CompressedTreeGraph big = simulate_compressed(example("leeuwenberg.toml"));
  const CompressedTreeGraph small = simulate_compressed(example("rauh.toml"));
  LineTree lines;
  reconstruct_lines_into(big, {}, lines);
  const std::size_t capacity = lines.capacity();
  reconstruct_lines_into(small, {}, lines);
  expect_same_plant(reconstruct(small, {}), lines, "rauh after leeuwenberg");
  EXPECT_GE(lines.capacity(), capacity);
}

TEST(LineReconstruction, AgeBeyondTheSimulationIsRefused) {
  const CompressedTreeGraph g = simulate_compressed(example("rauh.toml"));
  EXPECT_THROW(reconstruct_lines(g, {.age = g.final_age + 1.0}), ValueError);
}

}  // namespace
}  // namespace fspm::greenlab
