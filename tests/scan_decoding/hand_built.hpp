#pragma once
// Hand-built inputs of the reconstruction tests: a two-node skeleton, cube hulls, a small
// library whose eq. 3.3 choices can be worked out by hand, and a brute-force point-in-hull test
// by solid angles (independent of the library's ray parity).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include <limits>

#include "scan_decoding/cluster_texturing.hpp"
#include "scan_decoding/species_library.hpp"
#include "scans/cluster_model.hpp"

namespace fspm::scan_decoding::testing {

// The hand library has no unit: its patches scale to the hulls without the species' bound.
inline TextureOptions hand_options() {
  TextureOptions o;
  o.max_scale = std::numeric_limits<double>::infinity();
  return o;
}

// The 12 triangles of the box [lo, hi].
inline scans::ClusterHull box_hull(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                   NodeId seed) {
  scans::ClusterHull h;
  h.seed_node = seed;
  for (int k = 0; k < 8; ++k) {
    h.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(),
                            k & 4 ? hi.z() : lo.z());
  }
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    h.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[1]), std::uint32_t(q[2])});
    h.triangles.push_back({std::uint32_t(q[0]), std::uint32_t(q[2]), std::uint32_t(q[3])});
  }
  return h;
}

// Trunk (0,0,0)-(0,0,1), node 1 (0,0,1)-(0,0,2) above it and node 2 (0,0,1)-(2,0,1) beside it.
// Cluster 0 is the box [-1,1]^2 x [2.5,4.5] above node 1's end, cluster 1 the box
// [1,3] x [-1,1] x [1.5,3.5] above node 2's end (both seen straight up from their seed point,
// entered after 0.5 and left after 2.5), cluster 2 has no hull triangles.
inline scans::ClusterModel two_cluster_model() {
  scans::ClusterModel m;
  m.species = "default";
  NodeData d;
  d.end = {0, 0, 1};
  d.radius = 0.1;
  m.skeleton.add_node(kNoNode, d);
  d.start = {0, 0, 1}, d.end = {0, 0, 2}, d.radius = 0.06;
  m.skeleton.add_node(0, d);
  d.end = {2, 0, 1}, d.radius = 0.04, d.order = 1;
  m.skeleton.add_node(0, d);
  m.clusters.push_back(box_hull({-1, -1, 2.5}, {1, 1, 4.5}, 1));
  m.clusters.push_back(box_hull({1, -1, 1.5}, {3, 1, 3.5}, 2));
  scans::ClusterHull empty;
  empty.seed_node = 0;
  m.clusters.push_back(empty);
  return m;
}

// A straight patch of one internode of length 1 along `direction` with `leaves` leaves.
inline Patch straight_patch(const Eigen::Vector3d& direction, double thickness, int leaves) {
  Patch p;
  p.direction = direction.normalized();
  p.thickness = thickness;
  NodeData d;
  d.end = p.direction;
  d.radius = 0.05 * thickness;
  p.geometry.add_node(kNoNode, d);
  const Eigen::Vector3d side = p.direction.unitOrthogonal();
  for (int k = 0; k < leaves; ++k) {
    NodeData leaf;
    leaf.kind = OrganKind::kLeaf;
    leaf.start = p.direction * (0.2 + 0.15 * k);
    leaf.end = leaf.start + 0.2 * (k % 2 ? side : Eigen::Vector3d(-side));
    p.geometry.add_node(0, leaf);
  }
  p.leaves = static_cast<std::size_t>(leaves);
  p.length_m = 1.0;
  p.internode_length_m = 1.0;
  return p;
}

// Patch 0 "A": thickness 1 along +z, two docking points at 0.8 of its length leaving at 45
// degrees, thickness 0.5. Patch 1 "B": thickness 0.5 along +z, no docking points. Patch 2:
// thickness 3 (outside every S_s of thickness 1 or 0.5). Patch 3: thickness 1 pointing down
// (outside the 60 degrees of an upward seed).
inline SpeciesLibrary hand_library() {
  SpeciesLibrary lib;
  lib.species = "hand";
  Patch a = straight_patch(Eigen::Vector3d::UnitZ(), 1.0, 4);
  const double c = std::sqrt(0.5);
  a.dockings.push_back({0, {0, 0, 0.8}, {c, 0, c}, 0.5});
  a.dockings.push_back({0, {0, 0, 0.8}, {-c, 0, c}, 0.5});
  lib.patches.push_back(a);
  lib.patches.push_back(straight_patch(Eigen::Vector3d::UnitZ(), 0.5, 2));
  lib.patches.push_back(straight_patch(Eigen::Vector3d::UnitZ(), 3.0, 2));
  lib.patches.push_back(straight_patch(-Eigen::Vector3d::UnitZ(), 1.0, 2));
  return lib;
}

// Inside when the solid angles of the hull's triangles seen from `p` sum to +-4 pi
// (Van Oosterom and Strackee 1983); 0 outside.
inline bool inside_by_solid_angle(const scans::ClusterHull& hull, const Eigen::Vector3d& p) {
  double total = 0.0;
  for (const auto& t : hull.triangles) {
    const Eigen::Vector3d a = hull.vertices[t[0]] - p, b = hull.vertices[t[1]] - p,
                          c = hull.vertices[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    total += 2.0 * std::atan2(a.dot(b.cross(c)),
                              la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la);
  }
  return std::abs(std::abs(total) - 4.0 * std::numbers::pi) < 1e-6;
}

}  // namespace fspm::scan_decoding::testing
