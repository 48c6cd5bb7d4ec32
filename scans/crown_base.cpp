#include "scans/crown_base.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scans/allometry.hpp"

namespace fspm::scans {
namespace {

// The points of branch `c`'s first segment and of the segment `next` along it, off the surface of
// the trunk cylinder `trunk` (at a fork the nearest segment of trunk points is often the
// branch's).
std::vector<Eigen::Vector3d> branch_points(const PointSet& ps, NodeId c, NodeId next,
                                           const std::vector<std::uint32_t>& cylinder_of_point,
                                           const QsmCylinder& trunk) {
  const double off_m = trunk.radius_m + std::max(0.01, 0.1 * trunk.radius_m);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    if (cylinder_of_point[i] != c && cylinder_of_point[i] != next) continue;
    const Eigen::Vector3d v = ps.points[i] - trunk.start;
    if ((v - v.dot(trunk.axis) * trunk.axis).norm() > off_m) out.push_back(ps.points[i]);
  }
  return out;
}

struct Line {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
  bool elongated = false;  // spread along kMinAxisSpread times that across
};

Line principal_line(const std::vector<Eigen::Vector3d>& pts) {
  Line line;
  for (const Eigen::Vector3d& p : pts) line.centre += p;
  line.centre /= static_cast<double>(pts.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : pts) cov += (p - line.centre) * (p - line.centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d l = eig.eigenvalues().cwiseMax(0.0);  // ascending
  line.direction = eig.eigenvectors().col(2);
  line.elongated = l(2) > kMinAxisSpread * kMinAxisSpread * l(1);
  return line;
}

// The branch's axis: the principal line of its points, fitted again to those within twice the
// median distance of the first fit (a twig's or a neighbour's points in the segment).
Line branch_axis(std::vector<Eigen::Vector3d> pts) {
  const Line first = principal_line(pts);
  std::vector<double> d;
  for (const Eigen::Vector3d& p : pts) {
    const Eigen::Vector3d v = p - first.centre;
    d.push_back((v - v.dot(first.direction) * first.direction).norm());
  }
  std::vector<double> sorted = d;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(d.size() / 2),
                   sorted.end());
  const double keep_m = 2.0 * sorted[d.size() / 2] + 0.01;
  std::vector<Eigen::Vector3d> near;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (d[i] <= keep_m) near.push_back(pts[i]);
  }
  return near.size() >= 10 ? principal_line(near) : first;
}

// Where the branch's axis meets the trunk's axis: the trunk axis' point nearest to the branch's
// line. None when the points have no clear axis or run along the trunk, or when the lines pass
// further apart than the trunk's radius and kMaxAxisMissM, or meet further than `reach_m` from
// the fork node at `fork_z`.
std::optional<double> axis_base_z(const std::vector<Eigen::Vector3d>& pts, const QsmCylinder& trunk,
                                  double fork_z, double reach_m) {
  constexpr double kMaxAxisMissM = 0.1;
  if (pts.size() < 10) return std::nullopt;
  const Line line = branch_axis(pts);
  if (!line.elongated) return std::nullopt;
  const Eigen::Vector3d& d = line.direction;
  const double cos_ab = d.dot(trunk.axis);
  if (std::abs(cos_ab) > std::cos(kMinForkAngleDeg * std::numbers::pi / 180.0)) return std::nullopt;
  // Closest points of the lines trunk.start + s a and centre + r d (a, d unit).
  const Eigen::Vector3d w = trunk.start - line.centre;
  const double s = (cos_ab * w.dot(d) - w.dot(trunk.axis)) / (1.0 - cos_ab * cos_ab);
  const double r = (w.dot(d) - cos_ab * w.dot(trunk.axis)) / (1.0 - cos_ab * cos_ab);
  const Eigen::Vector3d on_trunk = trunk.start + s * trunk.axis;
  const double miss_m = (on_trunk - (line.centre + r * d)).norm();
  if (miss_m > trunk.radius_m + kMaxAxisMissM || std::abs(on_trunk.z() - fork_z) > reach_m) {
    return std::nullopt;
  }
  return on_trunk.z();
}

double low_side_z(std::vector<Eigen::Vector3d> pts) {
  const auto q = pts.begin() + static_cast<std::ptrdiff_t>(kBaseQuantile * (pts.size() - 1));
  std::nth_element(pts.begin(), q, pts.end(),
                   [](const auto& a, const auto& b) { return a.z() < b.z(); });
  return q->z();
}

}  // namespace

std::optional<double> crown_base_z(const PointSet& ps, const TreeGraph& t,
                                   const std::vector<std::uint32_t>& cylinder_of_point,
                                   const std::vector<QsmCylinder>& cylinders,
                                   double min_branch_length_m) {
  const std::vector<double> l = subtree_lengths_m(t);
  std::optional<double> lowest;
  for (NodeId u = 0; u < t.size(); ++u) {
    if (t.order(u) != 0) continue;
    for (NodeId c : t.children(u)) {
      if (t.order(c) == 0 || l[c] < min_branch_length_m) continue;
      // The first segment alone, else with the next one along the branch.
      const std::vector<Eigen::Vector3d> first =
          branch_points(ps, c, c, cylinder_of_point, cylinders[u]);
      NodeId next = c;
      for (NodeId k : t.children(c)) {
        if (t.order(k) == t.order(c)) next = k;
      }
      const std::vector<Eigen::Vector3d> two =
          branch_points(ps, c, next, cylinder_of_point, cylinders[u]);
      double z = t.end(u).z();
      const double reach_m = t.length(u) + t.length(c);
      std::optional<double> axis_z = axis_base_z(first, cylinders[u], z, reach_m);
      if (!axis_z) axis_z = axis_base_z(two, cylinders[u], z, reach_m);
      if (axis_z) {
        z = *axis_z;
      } else if (!first.empty()) {
        z = low_side_z(first);
      }
      lowest = std::min(lowest.value_or(z), z);
    }
  }
  return lowest;
}

}  // namespace fspm::scans
