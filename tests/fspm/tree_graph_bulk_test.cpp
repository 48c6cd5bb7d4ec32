// The bulk-building additions to TreeGraph (add_node_unchecked, Appender, clear_keep_capacity,
// advise_huge_pages) against the checked add_node path as the oracle.
#include <gtest/gtest.h>

#include <random>

#include "fspm/tree_graph.hpp"

namespace fspm {
namespace {

// A random plant-like tree as (parent, data) rows, lengths and unit directions given explicitly.
std::vector<std::pair<NodeId, NodeData>> random_rows(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::pair<NodeId, NodeData>> rows;
  for (std::size_t i = 0; i < n; ++i) {
    NodeData d;
    const NodeId parent =
        i == 0
            ? kNoNode
            : static_cast<NodeId>(
                  u(rng) > 0.6 ? i - 1 : std::uniform_int_distribution<std::size_t>(0, i - 1)(rng));
    d.start = Eigen::Vector3d(u(rng), u(rng), u(rng));
    d.direction = Eigen::Vector3d(u(rng), u(rng), 1.5).normalized();
    d.length = 0.5 + 0.5 * u(rng);
    d.end = d.start + d.length * d.direction;
    d.radius = 0.1 + 0.05 * u(rng);
    d.birth_time = static_cast<double>(i);
    d.physiological_age = static_cast<std::uint16_t>(1 + i % 3);
    d.order = static_cast<std::uint16_t>(i % 5);
    d.kind = i % 4 == 3 ? OrganKind::kLeaf : OrganKind::kInternode;
    rows.emplace_back(parent, d);
  }
  return rows;
}

TEST(TreeGraphBulk, UncheckedAddEqualsCheckedAdd) {
  const auto rows = random_rows(2000, 7);
  TreeGraph checked, unchecked;
  checked.add_attribute("light", 0.25);
  unchecked.add_attribute("light", 0.25);
  unchecked.reserve(rows.size());
  for (const auto& [parent, d] : rows) {
    checked.add_node(parent, d);
    unchecked.add_node_unchecked(parent, d);
  }
  EXPECT_TRUE(unchecked.identical(checked));
  EXPECT_EQ(unchecked.attribute("light")[1999], 0.25);
  // Children in insertion order, as add_node links them.
  std::size_t children = 0;
  for (NodeId n = 0; n < unchecked.size(); ++n) children += unchecked.child_count(n);
  EXPECT_EQ(children, rows.size() - 1);
}

TEST(TreeGraphBulk, ClearKeepCapacityRebuildsLikeNew) {
  const auto first = random_rows(5000, 1);
  const auto second = random_rows(3000, 2);
  TreeGraph reused;
  reused.add_attribute("dead", 0.0);
  reused.reserve(first.size());
  reused.advise_huge_pages();
  for (const auto& [parent, d] : first) reused.add_node_unchecked(parent, d);
  const std::size_t capacity = reused.capacity();
  ASSERT_GE(capacity, first.size());
  reused.clear_keep_capacity();
  EXPECT_TRUE(reused.empty());
  EXPECT_FALSE(reused.has_attribute("dead"));
  EXPECT_EQ(reused.capacity(), capacity);
  TreeGraph fresh;
  for (const auto& [parent, d] : second) {
    reused.add_node(parent, d);
    fresh.add_node(parent, d);
  }
  EXPECT_TRUE(reused.identical(fresh));
  EXPECT_EQ(reused.capacity(), capacity);  // no reallocation: 3000 <= capacity
}

// The appender against add_node as the oracle: into an empty graph and after existing nodes,
// with fewer, exactly as many and more nodes than it expected, attributes taking their defaults.
TEST(TreeGraphBulk, AppenderEqualsCheckedAdd) {
  const auto rows = random_rows(3000, 11);
  for (const std::size_t expected : {std::size_t{0}, std::size_t{1}, std::size_t{700},
                                     rows.size() - 1000, rows.size(), 5 * rows.size()}) {
    TreeGraph checked, appended;
    checked.add_attribute("light", 0.25);
    appended.add_attribute("light", 0.25);
    for (std::size_t r = 0; r < 1000; ++r) {  // existing nodes, added one by one
      checked.add_node(rows[r].first, rows[r].second);
      appended.add_node(rows[r].first, rows[r].second);
    }
    {
      TreeGraph::Appender append(appended, expected);
      for (std::size_t r = 1000; r < rows.size(); ++r) {
        checked.add_node(rows[r].first, rows[r].second);
        EXPECT_EQ(append.add(rows[r].first, rows[r].second), r);
        EXPECT_EQ(appended.parent(static_cast<NodeId>(r)), rows[r].first);  // readable at once
      }
      EXPECT_EQ(append.size(), rows.size());
    }  // finished here
    EXPECT_TRUE(appended.identical(checked)) << expected;
    EXPECT_EQ(appended.attribute("light")[2999], 0.25);
  }
}

TEST(TreeGraphBulk, AppenderDropsUnusedSlotsAndAddsAgainAfterFinish) {
  const auto rows = random_rows(300, 5);
  TreeGraph checked, appended;
  TreeGraph::Appender append(appended, 1000);
  for (std::size_t r = 0; r < 100; ++r) {
    append.add(rows[r].first, rows[r].second);
    checked.add_node(rows[r].first, rows[r].second);
  }
  append.finish();
  EXPECT_EQ(appended.size(), 100u);
  EXPECT_TRUE(appended.identical(checked));
  for (std::size_t r = 100; r < rows.size(); ++r) {
    append.add(rows[r].first, rows[r].second);
    checked.add_node(rows[r].first, rows[r].second);
  }
  append.finish();
  EXPECT_TRUE(appended.identical(checked));
  // An empty appender leaves the graph as it was.
  { TreeGraph::Appender idle(appended, 50); }
  EXPECT_TRUE(appended.identical(checked));
}

}  // namespace
}  // namespace fspm
