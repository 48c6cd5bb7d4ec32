// Reading the .clusters file (the declarations are in clusters_file.hpp).
#include <cmath>

#include "fspm/error.hpp"
#include "scans/byte_io.hpp"
#include "scans/clusters_file.hpp"

namespace fspm::scans {
namespace {

Eigen::Vector3d get_vector(ByteReader& r, const char* what) {
  const std::size_t at = r.offset();
  Eigen::Vector3d v;
  for (int c = 0; c < 3; ++c) v[c] = r.get<float>(what);
  if (!v.allFinite()) r.fail(std::string("a nan or infinite ") + what, at);
  return v;
}

void read_skeleton(ByteReader& r, ClusterModel& m, const Eigen::Vector3d& origin) {
  const std::size_t count_at = r.offset();
  const std::uint32_t n = r.get<std::uint32_t>("the skeleton node count");
  if (n == 0) r.fail("the skeleton has no node, expected at least the root", count_at);
  const Eigen::Vector3d root_start = get_vector(r, "the root start") + origin;
  // Each node takes at least its parent, position and radius: a count the file cannot hold is
  // refused before anything is reserved for it.
  constexpr std::size_t kNodeBytes = 4 + 3 * 4 + 4;
  if (n > r.remaining() / kNodeBytes) {
    r.fail("the skeleton node count " + std::to_string(n) + " needs more than the " +
               std::to_string(r.remaining()) + " bytes left",
           count_at);
  }
  m.skeleton.reserve(n);
  for (std::uint32_t u = 0; u < n; ++u) {
    const std::size_t at = r.offset();
    const std::uint32_t parent = r.get<std::uint32_t>("a skeleton node's parent");
    if ((u == 0) != (parent == 0xFFFFFFFFu) || (u > 0 && parent >= u)) {
      r.fail("node " + std::to_string(u) + " has parent " + std::to_string(parent) +
                 ", expected an earlier node (none for node 0)",
             at);
    }
    NodeData d;
    d.start = u == 0 ? root_start : m.skeleton.end(parent);
    d.end = get_vector(r, "a skeleton node's position") + origin;
    const float radius = r.get<float>("a skeleton node's radius");
    if (!(radius >= 0.0f) || !std::isfinite(radius)) r.fail("a negative or nan radius", at + 16);
    d.radius = radius;
    m.skeleton.add_node(u == 0 ? kNoNode : parent, d);
  }
}

ClusterHull read_hull(ByteReader& r, std::size_t nodes, bool has_length,
                      const Eigen::Vector3d& origin) {
  ClusterHull h;
  const std::size_t at = r.offset();
  h.seed_node = r.get<std::uint32_t>("a cluster's seed node");
  if (h.seed_node >= nodes) r.fail("the seed node is not a skeleton node", at);
  h.point_count = r.get<std::uint32_t>("a cluster's point count");
  if (has_length) {
    const std::size_t length_at = r.offset();
    const float length = r.get<float>("a cluster's branch length");
    if (!(length >= 0.0f) || !std::isfinite(length)) {
      r.fail("a negative or nan branch length", length_at);
    }
    h.branch_length_m = length;
  }
  const Eigen::Vector3d box_lo = get_vector(r, "a cluster's box");
  const Eigen::Vector3d side = get_vector(r, "a cluster's box") - box_lo;
  const Eigen::Vector3d lo = box_lo + origin;
  const std::uint16_t vertices = r.get<std::uint16_t>("a cluster's vertex count");
  const std::uint16_t triangles = r.get<std::uint16_t>("a cluster's triangle count");
  for (std::uint16_t k = 0; k < vertices; ++k) {
    Eigen::Vector3d v;
    for (int c = 0; c < 3; ++c) v[c] = lo[c] + side[c] * r.get<std::uint16_t>("a vertex") / 65535.0;
    h.vertices.push_back(v);
  }
  for (std::uint16_t k = 0; k < triangles; ++k) {
    const std::size_t tri_at = r.offset();
    std::array<std::uint32_t, 3> t{};
    for (std::uint32_t& i : t) i = r.get<std::uint16_t>("a triangle");
    if (t[0] >= vertices || t[1] >= vertices || t[2] >= vertices) {
      r.fail("a triangle refers to a vertex beyond the " + std::to_string(vertices), tri_at);
    }
    h.triangles.push_back(t);
  }
  return h;
}

}  // namespace

ClusterModel parse_clusters_bytes(std::string_view data, const std::string& path) {
  ByteReader r(data, path);
  const std::string_view magic =
      r.get_bytes(std::min(data.size(), kClustersMagic.size()), "the magic");
  if (magic != kClustersMagic && magic != kClustersMagicV1 && magic != kClustersMagicV3) {
    r.fail("not a .clusters file, expected it to start with FSPMCLU2 (or FSPMCLU1, FSPMCLU3)", 0);
  }
  const bool has_length = magic != kClustersMagicV1;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  if (magic == kClustersMagicV3) {
    const std::size_t at = r.offset();
    for (int c = 0; c < 3; ++c) origin[c] = r.get<double>("the origin");
    if (!origin.allFinite()) r.fail("a nan or infinite origin", at);
  }
  ClusterModel m;
  const std::uint8_t name_length = r.get<std::uint8_t>("the species name length");
  m.species = std::string(r.get_bytes(name_length, "the species name"));
  m.beta = r.get<float>("beta");
  m.gamma = r.get<float>("gamma");
  m.f_s = r.get<float>("f_s");
  m.root_diameter_m = r.get<float>("the root diameter");
  read_skeleton(r, m, origin);
  const std::uint32_t clusters = r.get<std::uint32_t>("the cluster count");
  for (std::uint32_t k = 0; k < clusters; ++k)
    m.clusters.push_back(read_hull(r, m.skeleton.size(), has_length, origin));
  if (!r.at_end()) r.fail("unexpected data after the last cluster", r.offset());
  return m;
}

}  // namespace fspm::scans
