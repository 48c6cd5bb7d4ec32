#include "fspm/compressed_tree_graph.hpp"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "fspm/error.hpp"

namespace fspm {
namespace {

// Jaeger et al. 2010, 2.2.2: the compressed table of the Figure 1 binary tree, entered by hand.
//   0 -> 1;  1 axillaries {2, 2};  2 -> 3;  3 ends with buds.
CompressedTreeGraph jaeger_table() {
  CompressedTreeGraph g;
  CompressedRecord r;
  r.birth = 1;
  const RecordId a = g.add_record(r);
  const std::array<RecordId, 2> lat{2, 2};
  const RecordId b = g.add_record(r, lat);
  r.birth = 2;
  const RecordId c = g.add_record(r);
  r.apex = ApexState::kBud;
  const RecordId d = g.add_record(r);
  g.set_successor(a, b);
  g.set_successor(c, d);
  g.set_apex(b, ApexState::kFlower);
  g.set_root(a);
  g.final_age = 2;
  return g;
}

TEST(CompressedTreeGraph, MultiplicitiesOfJaegerTable) {
  CompressedTreeGraph g = jaeger_table();
  EXPECT_EQ(g.compute_multiplicities(), 6u);  // 6 metamers in the explicit string of Figure 1
  EXPECT_EQ(g.record(0).multiplicity, 1u);
  EXPECT_EQ(g.record(1).multiplicity, 1u);
  EXPECT_EQ(g.record(2).multiplicity, 2u);
  EXPECT_EQ(g.record(3).multiplicity, 2u);
}

TEST(CompressedTreeGraph, ExpandGivesExplicitTree) {
  CompressedTreeGraph g = jaeger_table();
  g.compute_multiplicities();
  const TreeGraph t = g.expand();
  ASSERT_EQ(t.size(), 6u);
  // Jaeger's explicit table: 0 -> 1; 1 has laterals 2 and 4; 2 -> 3; 4 -> 5.
  EXPECT_EQ(t.parent(1), 0u);
  EXPECT_EQ(t.child_count(1), 2u);
  EXPECT_EQ(t.order(2), 1u);
  EXPECT_EQ(t.parent(3), 2u);
  EXPECT_EQ(t.birth_time(3), 2.0);
  const TreeGraph young = g.expand(1.0);  // birth-date filtering: only the first growth unit
  EXPECT_EQ(young.size(), 2u);
}

TEST(CompressedTreeGraph, EncodeDecodeRoundTrip) {
  CompressedTreeGraph g = jaeger_table();
  g.set_volumes(1, 0.5, 0.25, 1.0 / 3.0);
  g.metadata["age.count"] = 1;
  g.metadata["age.1.phyllotaxy_deg"] = 137.5;
  g.compute_multiplicities();
  const std::string bytes = encode_ctree(g);
  // Header 8 + 4 * 4 + 2 * 8 + 4, metadata (2 + 9 + 8) + (2 + 20 + 8), 4 records of 52 bytes,
  // 2 axillary references of 4 bytes.
  EXPECT_EQ(bytes.size(), 44u + 19u + 30u + 4u * 52u + 8u);
  const CompressedTreeGraph back = decode_ctree(bytes);
  EXPECT_TRUE(back == g);

  const auto path = (std::filesystem::temp_directory_path() / "fspm_ctree_test.ctree").string();
  write_ctree_file(g, path);
  EXPECT_TRUE(read_ctree_file(path) == g);
  std::filesystem::remove(path);
}

TEST(CompressedTreeGraph, RejectsBadFiles) {
  CompressedTreeGraph g = jaeger_table();
  g.compute_multiplicities();
  const std::string bytes = encode_ctree(g);
  std::string bad_magic = bytes;
  bad_magic[0] = 'X';
  EXPECT_THROW(decode_ctree(bad_magic), ParseError);
  std::string bad_version = bytes;
  bad_version[8] = 9;
  EXPECT_THROW(decode_ctree(bad_version), ParseError);
  EXPECT_THROW(decode_ctree(bytes.substr(0, bytes.size() - 3)), ParseError);
  // A wrong stored multiplicity (record 2, at its last 8 bytes) is caught.
  std::string bad_mult = bytes;
  const std::size_t records_at = 44;
  bad_mult[records_at + 2 * 52 + 44] = 7;
  EXPECT_THROW(decode_ctree(bad_mult), ParseError);
  // A successor pointing at itself makes a cycle.
  std::string cyc = bytes;
  cyc[records_at + 3 * 52] = 3;
  cyc[records_at + 3 * 52 + 1] = 0;
  cyc[records_at + 3 * 52 + 2] = 0;
  cyc[records_at + 3 * 52 + 3] = 0;
  EXPECT_THROW(decode_ctree(cyc), ParseError);
  EXPECT_THROW(read_ctree_file("/nonexistent/dir/x.ctree"), IoError);
}

TEST(CompressedTreeGraph, ValidateFindsCycle) {
  CompressedTreeGraph g;
  const RecordId a = g.add_record({});
  const RecordId b = g.add_record({});
  g.set_successor(a, b);
  g.set_successor(b, a);
  g.set_root(a);
  EXPECT_THROW(g.validate(), ValueError);
}

}  // namespace
}  // namespace fspm
