#include "environment/solid_push.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fspm::environment {

double signed_distance_to_solids(const Scene& scene, const Eigen::Vector3d& p,
                                 Eigen::Vector3d* normal) {
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_n = Eigen::Vector3d::UnitZ();
  const auto take = [&](double d, const Eigen::Vector3d& n) {
    if (d < best) {
      best = d;
      best_n = n;
    }
  };
  if (scene.ground && scene.ground->solid) take(p.z() - scene.ground->height_m, {0, 0, 1});
  for (const Box& b : scene.boxes) {
    if (!b.solid) continue;
    const Eigen::Vector3d local = b.rotation.transpose() * (p - b.center);
    const Eigen::Vector3d q = local.cwiseAbs() - b.half_extent;
    const Eigen::Vector3d sign = local.unaryExpr([](double x) { return x < 0 ? -1.0 : 1.0; });
    const Eigen::Vector3d outside = q.cwiseMax(0.0);
    if (outside.squaredNorm() > 0.0) {
      take(outside.norm(), (b.rotation * sign.cwiseProduct(outside)).normalized());
    } else {
      int axis = 0;
      q.maxCoeff(&axis);
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      n[axis] = sign[axis];
      take(q[axis], b.rotation * n);
    }
  }
  for (const Sphere& s : scene.spheres) {
    if (!s.solid) continue;
    const Eigen::Vector3d d = p - s.center;
    const double len = d.norm();
    take(len - s.radius_m, len > 0.0 ? Eigen::Vector3d(d / len) : Eigen::Vector3d::UnitZ());
  }
  if (normal != nullptr) *normal = best_n;
  return best;
}

std::size_t push_clusters_out_of_solids(const Scene& scene, TreeGraph& tree,
                                        std::vector<LeafCluster>& clusters) {
  std::size_t changed = 0;
  for (LeafCluster& c : clusters) {
    bool moved = false;
    // A cluster may touch several solids (a corner): a few rounds settle it.
    for (int round = 0; round < 4; ++round) {
      Eigen::Vector3d n;
      const double sd = signed_distance_to_solids(scene, c.center, &n);
      if (!(sd < c.radius_m - 1e-9)) break;
      const double r = c.radius_m;
      const double clipped = 0.5 * (r + sd);  // inscribed sphere of the free part of the hull
      if (clipped >= kMinClippedShare * r) {
        c.center += 0.5 * (r - sd) * n;
        c.translucency = std::pow(c.translucency, clipped / r);  // gamma0^r' (eq. 4.4)
        c.radius_m = clipped;
      } else {
        c.center += (r - sd + 1e-9) * n;
      }
      moved = true;
    }
    if (!moved) continue;
    ++changed;
    // Member nodes come parents first: a node starts where its moved parent now ends.
    std::vector<std::pair<NodeId, Eigen::Vector3d>> shifted;  // node, end offset
    for (const NodeId m : c.nodes) {
      const NodeId p = tree.parent(m);
      Eigen::Vector3d start = tree.start(m);
      for (const auto& [node, offset] : shifted) {
        if (node == p) start += offset;
      }
      Eigen::Vector3d end = tree.end(m);
      Eigen::Vector3d n;
      const double sd = signed_distance_to_solids(scene, end, &n);
      if (sd < 0.0) end += (1e-6 - sd) * n;
      if (start == tree.start(m) && end == tree.end(m)) continue;
      shifted.emplace_back(m, end - tree.end(m));
      const double len = tree.length(m);
      const Eigen::Vector3d dir = tree.direction(m);
      tree.set_segment(m, start, end);
      if (tree.kind(m) != OrganKind::kInternode) {
        tree.set_length(m, len);  // organs keep their own size and orientation
        tree.set_direction(m, dir);
      }
    }
  }
  return changed;
}

}  // namespace fspm::environment
