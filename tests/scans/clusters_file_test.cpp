// The .clusters file: a round trip within the documented quantization, and refused damage.
#include <gtest/gtest.h>

#include "fspm/error.hpp"
#include "scans/clusters_file.hpp"

namespace fspm::scans {
namespace {

ClusterModel small_model() {
  ClusterModel m;
  m.species = "pine";
  m.beta = 1.3, m.gamma = 1.2, m.f_s = 0.98, m.root_diameter_m = 0.3;
  NodeData d;
  d.end = {0, 0, 1};
  d.radius = 0.15;
  m.skeleton.add_node(kNoNode, d);
  d.start = {0, 0, 1}, d.end = {0.5, 0, 1.5}, d.radius = 0.05;
  m.skeleton.add_node(0, d);
  ClusterHull h;
  h.seed_node = 1;
  h.point_count = 1234;
  h.branch_length_m = 6.25;
  h.vertices = {{0, 0, 2}, {1, 0, 2}, {0, 1, 2}, {0, 0, 3}};
  h.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  m.clusters.push_back(h);
  return m;
}

TEST(ClustersFile, RoundTripWithinQuantization) {
  const ClusterModel m = small_model();
  const std::string bytes = clusters_bytes(m);
  // 8 magic + 1 + 4 name + 16 parameters + 4 + 12 root + 2 x 20 nodes + 4 + cluster
  // (4 + 4 + 4 + 24 + 2 + 2 + 4 x 6 + 4 x 6).
  EXPECT_EQ(bytes.size(), 8u + 1 + 4 + 16 + 4 + 12 + 40 + 4 + (40 + 48));
  EXPECT_EQ(bytes.substr(0, 8), "FSPMCLU2");
  const ClusterModel r = parse_clusters_bytes(bytes, "m.clusters");
  EXPECT_EQ(r.species, "pine");
  EXPECT_FLOAT_EQ(static_cast<float>(r.f_s), 0.98f);
  ASSERT_EQ(r.skeleton.size(), 2u);
  EXPECT_EQ(r.skeleton.parent(1), 0u);
  EXPECT_TRUE(r.skeleton.start(1).isApprox(Eigen::Vector3d(0, 0, 1)));
  EXPECT_NEAR(r.skeleton.radius(1), 0.05, 1e-7);
  ASSERT_EQ(r.clusters.size(), 1u);
  EXPECT_EQ(r.clusters[0].point_count, 1234u);
  EXPECT_EQ(r.clusters[0].branch_length_m, 6.25);  // exact in binary32
  EXPECT_EQ(r.clusters[0].triangles, m.clusters[0].triangles);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT((r.clusters[0].vertices[k] - m.clusters[0].vertices[k]).norm(), 1.0 / 65535 * 2);
  }
}

// Version 1 had no branch length: the same bytes without those 4, read with length 0.
TEST(ClustersFile, VersionOneIsReadWithoutBranchLengths) {
  std::string bytes = clusters_bytes(small_model());
  const std::size_t length_at = 8 + 1 + 4 + 16 + 4 + 12 + 40 + 4 + 8;
  bytes.erase(length_at, 4);
  bytes[7] = '1';
  const ClusterModel r = parse_clusters_bytes(bytes, "v1.clusters");
  ASSERT_EQ(r.clusters.size(), 1u);
  EXPECT_EQ(r.clusters[0].point_count, 1234u);
  EXPECT_EQ(r.clusters[0].branch_length_m, 0.0);
  EXPECT_EQ(r.clusters[0].triangles, small_model().clusters[0].triangles);
  bytes[7] = '4';
  EXPECT_THROW(parse_clusters_bytes(bytes, "v4.clusters"), ParseError);
}

TEST(ClustersFile, DamageIsRefusedWithTheByteOffset) {
  const std::string bytes = clusters_bytes(small_model());
  try {
    parse_clusters_bytes(bytes.substr(0, 60), "cut.clusters");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "cut.clusters");
    EXPECT_NE(e.message().find("at byte"), std::string::npos) << e.what();
  }
  std::string bad = bytes;
  bad[0] = 'X';
  EXPECT_THROW(parse_clusters_bytes(bad, "x.clusters"), ParseError);
  EXPECT_THROW(parse_clusters_bytes(bytes + "z", "y.clusters"), ParseError);
  // The second node's parent (offset 8 + 1 + 4 + 16 + 4 + 12 + 20) pointing at itself.
  bad = bytes;
  bad[65] = 1;
  EXPECT_THROW(parse_clusters_bytes(bad, "p.clusters"), ParseError);
  // A node count (offset 8 + 1 + 4 + 16) of 2^32 - 1 is refused before anything is reserved.
  bad = bytes;
  for (int k = 29; k < 33; ++k) bad[k] = '\xff';
  try {
    parse_clusters_bytes(bad, "n.clusters");
    FAIL() << "expected a ParseError";
  } catch (const ParseError& e) {
    EXPECT_NE(e.message().find("node count 4294967295"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fspm::scans

namespace fspm::scans {
namespace {

// At projected coordinates a float keeps half a metre; version 3 stores a double origin and
// floats relative to it, so positions come back to float precision at the origin (~1e-6 m).
TEST(ClustersFile, ProjectedCoordinatesKeepMillimetresThroughTheOrigin) {
  ClusterModel m = small_model();
  const Eigen::Vector3d shift(500000.123, 5800000.456, 300.789);
  ClusterModel far = m;
  far.skeleton = TreeGraph();
  for (NodeId u = 0; u < m.skeleton.size(); ++u) {
    NodeData d;
    d.start = m.skeleton.start(u) + shift;
    d.end = m.skeleton.end(u) + shift;
    d.radius = m.skeleton.radius(u);
    far.skeleton.add_node(m.skeleton.parent(u), d);
  }
  for (Eigen::Vector3d& v : far.clusters[0].vertices) v += shift;
  const std::string bytes = clusters_bytes(far);
  EXPECT_EQ(bytes.substr(0, 8), "FSPMCLU3");
  EXPECT_EQ(bytes.size(), clusters_bytes(m).size() + 24);
  const ClusterModel r = parse_clusters_bytes(bytes, "far.clusters");
  for (NodeId u = 0; u < m.skeleton.size(); ++u) {
    EXPECT_LT((r.skeleton.end(u) - far.skeleton.end(u)).norm(), 1e-5);
    EXPECT_LT((r.skeleton.start(u) - far.skeleton.start(u)).norm(), 1e-5);
  }
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_LT((r.clusters[0].vertices[k] - far.clusters[0].vertices[k]).norm(), 1e-4);
  }
}

}  // namespace
}  // namespace fspm::scans
