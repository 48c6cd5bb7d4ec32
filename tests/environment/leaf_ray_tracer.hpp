#pragma once
// A Monte Carlo ray tracer over explicit leaf and branch triangles, the yardstick of the leaf
// light (tests/environment/light_yardstick_test.cpp, bench/canopy_light_bench.cpp); kept out of
// the libraries. Each cluster's leaves are triangles placed uniformly in its sphere with uniformly
// random orientations (a spherical leaf angle distribution) and the leaf area of the turbid medium
// the light models assume (cluster_leaf_area_m2); internodes are opaque hexagonal prisms. Rays
// leave random points of a cluster's leaves toward the cos^2 zenith sky of eq. 4.3 (importance
// sampled: cos(theta) = u^(1/3)); the share that escapes is the mean sky light of its leaves.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "environment/canopy_light.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm::environment::yardstick {

struct Triangle {
  Eigen::Vector3d a, b, c;
};

struct Aabb {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  void grow(const Eigen::Vector3d& p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); }
  bool hit(const Eigen::Vector3d& o, const Eigen::Vector3d& inv) const {
    double t0 = 0.0, t1 = 1e300;
    for (int k = 0; k < 3; ++k) {
      double a = (lo[k] - o[k]) * inv[k], b = (hi[k] - o[k]) * inv[k];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    return t0 <= t1;
  }
};

// A plain bounding volume hierarchy (median split on the longest axis), any-hit queries.
class Bvh {
 public:
  explicit Bvh(std::vector<Triangle> tris) : tris_(std::move(tris)) {
    order_.resize(tris_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    build(0, static_cast<std::uint32_t>(order_.size()));
  }
  // True when the ray o + t d (t > 1e-9) hits a triangle other than `ignore`.
  bool occluded(const Eigen::Vector3d& o, const Eigen::Vector3d& d, std::uint32_t ignore) const {
    const Eigen::Vector3d inv(1.0 / d.x(), 1.0 / d.y(), 1.0 / d.z());
    std::array<std::uint32_t, 64> stack;
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (!n.box.hit(o, inv)) continue;
      if (n.count > 0) {
        for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
          if (order_[k] != ignore && intersects(tris_[order_[k]], o, d)) return true;
        }
      } else {
        stack[top++] = n.left;
        stack[top++] = n.right;
      }
    }
    return false;
  }

 private:
  struct Node {
    Aabb box;
    std::uint32_t left = 0, right = 0, first = 0, count = 0;
  };
  static bool intersects(const Triangle& t, const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    // Moeller and Trumbore (1997).
    const Eigen::Vector3d e1 = t.b - t.a, e2 = t.c - t.a, p = d.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-14) return false;
    const Eigen::Vector3d s = o - t.a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = d.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    return e2.dot(q) / det > 1e-9;
  }
  std::uint32_t build(std::uint32_t first, std::uint32_t end) {
    const std::uint32_t id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    Aabb box, centres;
    for (std::uint32_t k = first; k < end; ++k) {
      const Triangle& t = tris_[order_[k]];
      box.grow(t.a), box.grow(t.b), box.grow(t.c);
      centres.grow((t.a + t.b + t.c) / 3.0);
    }
    nodes_[id].box = box;
    if (end - first <= 4) {
      nodes_[id].first = first, nodes_[id].count = end - first;
      return id;
    }
    int axis = 0;
    (centres.hi - centres.lo).maxCoeff(&axis);
    const std::uint32_t mid = (first + end) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t x, std::uint32_t y) {
                       const Triangle &p = tris_[x], &q = tris_[y];
                       return p.a[axis] + p.b[axis] + p.c[axis] < q.a[axis] + q.b[axis] + q.c[axis];
                     });
    const std::uint32_t left = build(first, mid);
    const std::uint32_t right = build(mid, end);
    nodes_[id].left = left, nodes_[id].right = right;
    return id;
  }
  std::vector<Triangle> tris_;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
};

inline constexpr double kLeafArea_m2 = 0.004;  // one leaf blade (a triangle), about a 9 cm leaf

inline Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Eigen::Vector3d v(n(rng), n(rng), n(rng));
  return v.normalized();
}

// Leaves of every cluster (triangles, cluster by cluster: leaf_start[c] .. leaf_start[c + 1]).
inline std::vector<Triangle> leaf_triangles(std::span<const Sphere> clusters, std::mt19937_64& rng,
                                            std::vector<std::uint32_t>& leaf_start) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Triangle> out;
  leaf_start.assign(1, 0);
  for (const Sphere& c : clusters) {
    const double area = cluster_leaf_area_m2(c);
    const int n = std::max(1, static_cast<int>(std::lround(area / kLeafArea_m2)));
    // Equilateral triangle of area A: side s = sqrt(4 A / sqrt 3), circumradius s / sqrt 3.
    const double side = std::sqrt(4.0 * area / n / std::sqrt(3.0));
    const double circum = side / std::sqrt(3.0);
    for (int k = 0; k < n; ++k) {
      Eigen::Vector3d p;
      do p = Eigen::Vector3d(u(rng), u(rng), u(rng));
      while (p.squaredNorm() > 1.0);
      p = c.center + c.radius_m * p;
      const Eigen::Vector3d normal = random_unit(rng);
      const Eigen::Vector3d e1 = normal.unitOrthogonal();
      const Eigen::Vector3d e2 = normal.cross(e1);
      const double phi = std::numbers::pi * u(rng);
      std::array<Eigen::Vector3d, 3> v;
      for (int i = 0; i < 3; ++i) {
        const double a = phi + 2.0 * std::numbers::pi * i / 3.0;
        v[i] = p + circum * (std::cos(a) * e1 + std::sin(a) * e2);
      }
      out.push_back({v[0], v[1], v[2]});
    }
    leaf_start.push_back(static_cast<std::uint32_t>(out.size()));
  }
  return out;
}

// Internodes as opaque hexagonal prisms (12 triangles each).
inline void add_wood(const TreeGraph& tree, std::vector<Triangle>& out) {
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (tree.kind(i) != OrganKind::kInternode) continue;
    const Eigen::Vector3d a = tree.start(i), b = tree.end(i);
    const Eigen::Vector3d axis = b - a;
    if (axis.norm() <= 0.0) continue;
    const Eigen::Vector3d e1 = axis.normalized().unitOrthogonal();
    const Eigen::Vector3d e2 = axis.normalized().cross(e1);
    const double r = tree.radius(i);
    for (int k = 0; k < 6; ++k) {
      const double t0 = std::numbers::pi * k / 3.0, t1 = std::numbers::pi * (k + 1) / 3.0;
      const Eigen::Vector3d o0 = r * (std::cos(t0) * e1 + std::sin(t0) * e2);
      const Eigen::Vector3d o1 = r * (std::cos(t1) * e1 + std::sin(t1) * e2);
      out.push_back({a + o0, a + o1, b + o1});
      out.push_back({a + o0, b + o1, b + o0});
    }
  }
}

// Mean sky light (cos^2 zenith sky) of each cluster's leaves: `leaves` sampled leaves per cluster,
// `rays` rays from random points of each.
inline std::vector<double> traced_light(const Bvh& bvh, std::span<const Triangle> tris,
                                        std::span<const std::uint32_t> leaf_start, int leaves,
                                        int rays, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> out;
  for (std::size_t c = 0; c + 1 < leaf_start.size(); ++c) {
    const std::uint32_t n = leaf_start[c + 1] - leaf_start[c];
    std::size_t open = 0, total = 0;
    for (int l = 0; l < leaves; ++l) {
      const std::uint32_t id = leaf_start[c] + static_cast<std::uint32_t>(u(rng) * n) % n;
      const Triangle& t = tris[id];
      for (int k = 0; k < rays; ++k) {
        double a = u(rng), b = u(rng);
        if (a + b > 1.0) a = 1.0 - a, b = 1.0 - b;
        const Eigen::Vector3d p = t.a + a * (t.b - t.a) + b * (t.c - t.a);
        const double cz = std::cbrt(u(rng)), sz = std::sqrt(1.0 - cz * cz);
        const double phi = 2.0 * std::numbers::pi * u(rng);
        const Eigen::Vector3d d(sz * std::cos(phi), sz * std::sin(phi), cz);
        open += !bvh.occluded(p, d, id);
        ++total;
      }
    }
    out.push_back(static_cast<double>(open) / static_cast<double>(total));
  }
  return out;
}

}  // namespace fspm::environment::yardstick
