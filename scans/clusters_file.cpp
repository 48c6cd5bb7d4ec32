#include "scans/clusters_file.hpp"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "scans/byte_io.hpp"

namespace fspm::scans {
namespace {

constexpr std::uint32_t kNoParent = 0xFFFFFFFFu;

void put_vec(ByteWriter& w, const Eigen::Vector3d& v) {
  for (int c = 0; c < 3; ++c) w.put(static_cast<float>(v[c]));
}

void put_hull(ByteWriter& w, ClusterHull h, const Eigen::Vector3d& origin) {
  for (Eigen::Vector3d& v : h.vertices) v -= origin;
  if (h.vertices.size() > 65535 || h.triangles.size() > 65535) {
    throw ValueError("a cluster hull has more than 65535 vertices or triangles");
  }
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
  if (!h.vertices.empty()) lo = hi = h.vertices[0];
  for (const Eigen::Vector3d& v : h.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  w.put(static_cast<std::uint32_t>(h.seed_node));
  w.put(h.point_count);
  w.put(static_cast<float>(h.branch_length_m));
  put_vec(w, lo);
  put_vec(w, hi);
  w.put(static_cast<std::uint16_t>(h.vertices.size()));
  w.put(static_cast<std::uint16_t>(h.triangles.size()));
  const Eigen::Vector3d lo_f = lo.cast<float>().cast<double>();
  const Eigen::Vector3d side = hi.cast<float>().cast<double>() - lo_f;
  for (const Eigen::Vector3d& v : h.vertices) {
    for (int c = 0; c < 3; ++c) {
      const double t = side[c] > 0.0 ? (v[c] - lo_f[c]) / side[c] : 0.0;
      w.put(static_cast<std::uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0)));
    }
  }
  for (const auto& t : h.triangles) {
    for (std::uint32_t i : t) w.put(static_cast<std::uint16_t>(i));
  }
}

}  // namespace

std::string clusters_bytes(const ClusterModel& m) {
  if (m.skeleton.empty()) throw ValueError("a cluster model needs at least the root node");
  if (m.species.size() > 255) throw ValueError("the species name is longer than 255 bytes");
  ByteWriter w;
  const Eigen::Vector3d& root = m.skeleton.start(0);
  const bool far = root.cwiseAbs().maxCoeff() > kClustersOriginAfterM;
  const Eigen::Vector3d origin =
      far ? Eigen::Vector3d(root.array().floor().matrix()) : Eigen::Vector3d::Zero();
  w.put_bytes(far ? kClustersMagicV3 : kClustersMagic);
  if (far) {
    for (int c = 0; c < 3; ++c) w.put(origin[c]);
  }
  w.put(static_cast<std::uint8_t>(m.species.size()));
  w.put_bytes(m.species);
  for (double v : {m.beta, m.gamma, m.f_s, m.root_diameter_m}) w.put(static_cast<float>(v));
  w.put(static_cast<std::uint32_t>(m.skeleton.size()));
  put_vec(w, m.skeleton.start(0) - origin);
  for (NodeId u = 0; u < m.skeleton.size(); ++u) {
    w.put(m.skeleton.parent(u) == kNoNode ? kNoParent : m.skeleton.parent(u));
    put_vec(w, m.skeleton.end(u) - origin);
    w.put(static_cast<float>(m.skeleton.radius(u)));
  }
  w.put(static_cast<std::uint32_t>(m.clusters.size()));
  for (const ClusterHull& h : m.clusters) put_hull(w, h, origin);
  return std::move(w.bytes());
}

void write_clusters_file(const ClusterModel& model, const std::string& path) {
  const std::string bytes = clusters_bytes(model);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      },
      true);
}

ClusterModel read_clusters_file(const std::string& path) {
  return parse_clusters_bytes(read_input_file(path), path);
}

}  // namespace fspm::scans
