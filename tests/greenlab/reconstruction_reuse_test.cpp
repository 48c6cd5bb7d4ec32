// reconstruct_into reuses a TreeGraph: whatever it held before (another plant, attributes), the
// result equals a reconstruction into a new graph, at every age.
#include <gtest/gtest.h>

#include "greenlab/expand.hpp"
#include "greenlab/simulation.hpp"
#include "test_plants.hpp"

namespace fspm::greenlab {
namespace {

using testing::example;

TEST(ReconstructionReuse, SameTreeAsAFreshGraphAtEveryAge) {
  const CompressedTreeGraph rauh = simulate_compressed(example("rauh.toml"));
  const CompressedTreeGraph leeuwenberg = simulate_compressed(example("leeuwenberg.toml"));
  TreeGraph reused;
  reconstruct_into(leeuwenberg, {}, reused);  // a bigger, different plant first
  reused.add_attribute("stale", 3.0);
  const std::size_t capacity = reused.capacity();
  ASSERT_GT(reused.size(), 0u);
  for (double age = 0.0; age <= rauh.final_age; age += 1.0) {
    ReconstructionStats fresh_stats, reused_stats;
    const TreeGraph fresh = reconstruct(rauh, {.age = age}, &fresh_stats);
    reconstruct_into(rauh, {.age = age}, reused, &reused_stats);
    EXPECT_TRUE(reused.identical(fresh)) << "age " << age;
    EXPECT_EQ(reused_stats.components(), fresh_stats.components());
    EXPECT_FALSE(reused.has_attribute("stale"));
  }
  EXPECT_GE(reused.capacity(), capacity);
}

}  // namespace
}  // namespace fspm::greenlab
