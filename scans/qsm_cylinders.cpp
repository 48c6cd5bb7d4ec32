#include "scans/qsm_cylinders.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "fspm/error.hpp"
#include "scans/circle_fit.hpp"
#include "scans/point_kd_tree.hpp"

namespace fspm::scans {
namespace {

// Distance of p from the segment a-b.
double segment_point_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& p) {
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double t = l2 > 0.0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Each point's nearest segment: samples along every segment (at most a quarter of the shortest
// typical segment apart) in a k-d tree; of the segments of the 4 nearest samples, the nearest.
std::vector<std::uint32_t> nearest_segments(const PointSet& ps, const TreeGraph& t) {
  std::vector<double> lengths;
  for (NodeId u = 0; u < t.size(); ++u) lengths.push_back(t.length(u));
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double step = std::max(0.25 * lengths[lengths.size() / 2], 1e-3);
  std::vector<Eigen::Vector3d> samples;
  std::vector<std::uint32_t> owner;
  for (NodeId u = 0; u < t.size(); ++u) {
    const int n = 1 + static_cast<int>(std::min(1000.0, std::ceil(t.length(u) / step)));
    for (int k = 0; k <= n; ++k) {
      samples.push_back(t.start(u) + (t.end(u) - t.start(u)) * (static_cast<double>(k) / n));
      owner.push_back(u);
    }
  }
  PointCloudAdaptor adaptor{&samples};
  PointKdTree tree(3, adaptor, nanoflann::KDTreeSingleIndexAdaptorParams(16));
  tree.buildIndex();
  std::vector<std::uint32_t> out(ps.points.size());
  std::uint32_t idx[4];
  double d2[4];
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const std::size_t found = tree.knnSearch(ps.points[i].data(), 4, idx, d2);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < found; ++k) {
      const NodeId u = owner[idx[k]];
      const double d = segment_point_distance(t.start(u), t.end(u), ps.points[i]);
      if (d < best) best = d, out[i] = u;
    }
  }
  return out;
}

// Radius and axis offset of one segment from its points (see the header); false when the circle
// fit was replaced by the median distance.
bool fit_segment(const std::vector<Eigen::Vector3d>& pts, QsmCylinder& c) {
  const Eigen::Vector3d a = c.axis;
  const Eigen::Vector3d e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  std::vector<Eigen::Vector2d> q;
  std::vector<double> dist;
  for (const Eigen::Vector3d& p : pts) {
    const Eigen::Vector3d v = p - c.start;
    q.emplace_back(v.dot(e1), v.dot(e2));
    dist.push_back(q.back().norm());
  }
  if (dist.empty()) return false;
  std::nth_element(dist.begin(), dist.begin() + dist.size() / 2, dist.end());
  const double median = dist[dist.size() / 2];
  const std::optional<Circle> circle = pts.size() >= 5 ? fit_circle_kasa(q) : std::nullopt;
  if (circle && circle->rms_m < circle->radius_m / 6.0 && circle->radius_m < 2.0 * median + 0.01) {
    c.radius_m = circle->radius_m;
    c.start += circle->centre.x() * e1 + circle->centre.y() * e2;
    return true;
  }
  c.radius_m = median;
  return false;
}

// The points of a branch's first segment off the surface of its parent: at a fork the nearest
// segment of many parent surface points is the branch's, and they would give it the parent's
// radius. All points when fewer than 5 are left.
std::vector<Eigen::Vector3d> outside_parent(const std::vector<Eigen::Vector3d>& pts,
                                            const QsmCylinder& parent) {
  const Eigen::Vector3d end = parent.start + parent.length_m * parent.axis;
  const double margin = std::max(0.01, 0.1 * parent.radius_m);
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& p : pts) {
    if (segment_point_distance(parent.start, end, p) > parent.radius_m + margin) out.push_back(p);
  }
  return out.size() >= 5 ? out : pts;
}

// Branch index per node: a new branch where the order changes (or at the root).
void number_branches(const TreeGraph& t, std::vector<QsmCylinder>& cyl) {
  std::int64_t next = 0;
  for (NodeId u = 0; u < t.size(); ++u) {
    const NodeId p = t.parent(u);
    if (p == kNoNode || t.order(p) != t.order(u)) {
      cyl[u].branch = next++;
    } else {
      cyl[u].branch = cyl[p].branch;
    }
  }
}

// Whether p lies inside the cylinder o (within its length and radius).
bool contains(const QsmCylinder& o, const Eigen::Vector3d& p) {
  const double t = (p - o.start).dot(o.axis);
  return t > 0.0 && t < o.length_m && (p - o.start - t * o.axis).norm() < o.radius_m;
}

Eigen::Vector3d middle(const QsmCylinder& c) { return c.start + 0.5 * c.length_m * c.axis; }

// Marks cylinders whose axis middle lies inside a wider one (equal radii: the later one).
void mark_nested(std::vector<QsmCylinder>& cyl) {
  for (std::size_t i = 0; i < cyl.size(); ++i) {
    const Eigen::Vector3d mid = middle(cyl[i]);
    for (std::size_t j = 0; j < cyl.size() && !cyl[i].nested; ++j) {
      const QsmCylinder& o = cyl[j];
      const bool wider = o.radius_m > cyl[i].radius_m || (o.radius_m == cyl[i].radius_m && j < i);
      if (j == i || !wider) continue;
      cyl[i].nested = contains(o, mid);
    }
  }
}

// Skeleton length of each node's subtree, its own segment included (parents precede children).
std::vector<double> subtree_lengths(const TreeGraph& t) {
  std::vector<double> l(t.size(), 0.0);
  for (NodeId u = t.size(); u-- > 0;) {
    l[u] += t.length(u);
    if (t.parent(u) != kNoNode) l[t.parent(u)] += l[u];
  }
  return l;
}

// As in TreeQSM, a branch cylinder is never wider than its parent, nor is a trunk cylinder
// without a circle fit (the scattered points of a crown's top).
void cap_by_parent(const TreeGraph& t, NodeId u, bool fitted, std::vector<QsmCylinder>& cyl) {
  const NodeId p = t.parent(u);
  if (p != kNoNode && (cyl[u].order > 0 || !fitted)) {
    cyl[u].radius_m = std::min(cyl[u].radius_m, cyl[p].radius_m);
  }
}

// Whether the middle of cylinder u lies inside a fitted cylinder at least as wide: a short false
// fork of the skeleton at a junction, which holds the stem's surface points.
bool inside_fitted(const std::vector<QsmCylinder>& cyl, const std::vector<char>& fitted,
                   std::size_t u) {
  for (std::size_t j = 0; j < cyl.size(); ++j) {
    if (j != u && fitted[j] && cyl[j].radius_m >= cyl[u].radius_m &&
        contains(cyl[j], middle(cyl[u]))) {
      return true;
    }
  }
  return false;
}

// The radius of a segment without a circle fit. The median distance of its points from the axis
// measures the spread of what surrounds a branch in a crown (leaves, needles, twigs) as much as
// the branch, and made the cylinders of leafy crowns as wide as their parents (a woody volume
// four times TreeQSM's on a leafy tree). The pipe model (Shinozaki et al. 1964; area-preserving
// branching, Leonardo's rule, Eloy 2011) carries the radius of the nearest fitted ancestor a (or
// the root) instead: the cross-section is proportional to what the branch carries, here its
// subtree's skeleton length, r = r_a sqrt(L(u) / L(a)); the smaller of the two is kept. False forks
// inside a fitted stem keep the median distance of the stem's points (they are left out as nested).
void carry_pipe_radii(const TreeGraph& t, const std::vector<char>& fitted,
                      std::vector<QsmCylinder>& cyl) {
  const std::vector<double> carried = subtree_lengths(t);
  // The nearest ancestor with a circle fit, or the root: the stem's foot, whose points' median
  // distance from the axis is its radius where noise or a misregistered scan fails the fit.
  std::vector<NodeId> anchor(t.size(), kNoNode);
  for (NodeId u = 0; u < t.size(); ++u) {
    const NodeId p = t.parent(u);
    anchor[u] = fitted[u] || p == kNoNode ? u : anchor[p];
    const NodeId a = anchor[u];
    if (!fitted[u] && a != kNoNode && carried[a] > 0.0 && !inside_fitted(cyl, fitted, u)) {
      cyl[u].radius_m =
          std::min(cyl[u].radius_m, cyl[a].radius_m * std::sqrt(carried[u] / carried[a]));
    }
    cap_by_parent(t, u, fitted[u], cyl);
  }
}

}  // namespace

QsmCylinders fit_qsm_cylinders(const PointSet& ps, const TreeGraph& t) {
  if (t.empty()) throw ValueError("fitting cylinders needs a skeleton with at least one node");
  QsmCylinders out;
  out.cylinder_of_point = nearest_segments(ps, t);
  std::vector<std::vector<Eigen::Vector3d>> members(t.size());
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    members[out.cylinder_of_point[i]].push_back(ps.points[i]);
  }
  out.cylinders.resize(t.size());
  std::vector<char> fitted(t.size(), 0);
  for (NodeId u = 0; u < t.size(); ++u) {
    QsmCylinder& c = out.cylinders[u];
    c.start = t.start(u);
    c.length_m = t.length(u);
    if (c.length_m > 0.0) c.axis = (t.end(u) - t.start(u)) / c.length_m;
    c.parent = t.parent(u) == kNoNode ? -1 : static_cast<std::int64_t>(t.parent(u));
    c.order = t.order(u);
    const NodeId p = t.parent(u);
    fitted[u] = fit_segment(p != kNoNode && t.order(p) < c.order
                                ? outside_parent(members[u], out.cylinders[p])
                                : members[u],
                            c);
    cap_by_parent(t, u, fitted[u], out.cylinders);
  }
  carry_pipe_radii(t, fitted, out.cylinders);
  number_branches(t, out.cylinders);
  mark_nested(out.cylinders);
  out.surface_distance_m.resize(ps.points.size());
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const QsmCylinder& c = out.cylinders[out.cylinder_of_point[i]];
    const double d = segment_point_distance(c.start, c.start + c.length_m * c.axis, ps.points[i]);
    out.surface_distance_m[i] = std::abs(d - c.radius_m);
  }
  return out;
}

double cylinders_volume_m3(const std::vector<QsmCylinder>& cylinders) {
  double v = 0.0;
  for (const QsmCylinder& c : cylinders)
    v += c.nested ? 0.0 : std::numbers::pi * c.radius_m * c.radius_m * c.length_m;
  return v;
}

}  // namespace fspm::scans
