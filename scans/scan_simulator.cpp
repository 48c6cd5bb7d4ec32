#include "scans/scan_simulator.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/number_text.hpp"
#include "scans/segment_distance.hpp"

namespace fspm::scans {
namespace {

constexpr int kAzimuthCells = 720;
constexpr int kElevationCells = 360;
constexpr double kPi = std::numbers::pi;

bool scanned(const TreeGraph& t, NodeId u, const ScanOptions& o) {
  return t.kind(u) == OrganKind::kInternode && t.radius(u) > 0.0 && t.radius(u) >= o.min_radius_m &&
         t.length(u) > 0.0;
}

// The internodes each line-of-sight direction from one scanner may cross, by angular cell.
class OccluderGrid {
 public:
  OccluderGrid(const TreeGraph& t, const ScanOptions& o, const Eigen::Vector3d& s)
      : cells_(kAzimuthCells * kElevationCells) {
    for (NodeId u = 0; u < t.size(); ++u) {
      if (!scanned(t, u, o)) continue;
      const Eigen::Vector3d c = 0.5 * (t.start(u) + t.end(u)) - s;
      const double reach = 0.5 * t.length(u) + t.radius(u);
      const double dist = c.norm();
      const double alpha = dist > reach ? std::asin(reach / dist) : kPi;
      const double el = std::asin(std::clamp(c.z() / std::max(dist, 1e-12), -1.0, 1.0));
      const double az = std::atan2(c.y(), c.x());
      const double half_az =
          std::min(kPi, alpha / std::max(std::cos(std::min(std::abs(el) + alpha, kPi / 2)), 0.02));
      for (int e = cell_el(el - alpha); e <= cell_el(el + alpha); ++e) {
        const int a0 =
            static_cast<int>(std::floor((az - half_az + kPi) / (2 * kPi) * kAzimuthCells));
        const int a1 =
            static_cast<int>(std::floor((az + half_az + kPi) / (2 * kPi) * kAzimuthCells));
        for (int a = a0; a <= std::min(a1, a0 + kAzimuthCells - 1); ++a) {
          cells_[static_cast<std::size_t>(((a % kAzimuthCells) + kAzimuthCells) % kAzimuthCells) *
                     kElevationCells +
                 static_cast<std::size_t>(e)]
              .push_back(u);
        }
      }
    }
  }
  const std::vector<NodeId>& at(const Eigen::Vector3d& d) const {
    const double el = std::asin(std::clamp(d.z() / d.norm(), -1.0, 1.0));
    int a =
        static_cast<int>(std::floor((std::atan2(d.y(), d.x()) + kPi) / (2 * kPi) * kAzimuthCells));
    a = std::clamp(a, 0, kAzimuthCells - 1);
    return cells_[static_cast<std::size_t>(a) * kElevationCells +
                  static_cast<std::size_t>(cell_el(el))];
  }

 private:
  static int cell_el(double el) {
    return std::clamp(static_cast<int>(std::floor((el + kPi / 2) / kPi * kElevationCells)), 0,
                      kElevationCells - 1);
  }
  std::vector<std::vector<NodeId>> cells_;
};

bool occluded(const TreeGraph& t, const OccluderGrid& grid, NodeId self, const Eigen::Vector3d& s,
              const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = p - s;
  const Eigen::Vector3d stop = p - d.normalized() * 1e-3;
  for (NodeId v : grid.at(d)) {
    if (v == self || v == t.parent(self) || t.parent(v) == self) continue;
    if (segment_distance(s, stop, t.start(v), t.end(v)) < t.radius(v)) return true;
  }
  return false;
}

// Candidates of internode u nearer to scanner s than the reference distance d0 are drawn
// (d0 / near)^2 times as densely and thinned by the same factor.
double near_boost(const TreeGraph& t, NodeId u, const Eigen::Vector3d& s, double d0) {
  const double near =
      std::max((0.5 * (t.start(u) + t.end(u)) - s).norm() - 0.5 * t.length(u) - t.radius(u), 0.1);
  return std::max(1.0, (d0 / near) * (d0 / near));
}

// The points a scan keeps, checked against the memory limit before it starts. A candidate
// point is kept with probability |cos incidence| (d0 / range)^2 / boost on the half of the
// cylinder facing the scanner: on average at most 1 / pi of the candidates drawn.
void check_scan_memory(const TreeGraph& t, const std::vector<Eigen::Vector3d>& scanners,
                       const ScanOptions& o) {
  double candidates = 0.0;
  for (const Eigen::Vector3d& s : scanners) {
    const double d0 = (s - t.start(0)).head<2>().norm();
    for (NodeId u = 0; u < t.size(); ++u) {
      if (!scanned(t, u, o)) continue;
      candidates +=
          o.density_per_m2 * 2 * kPi * t.radius(u) * t.length(u) * near_boost(t, u, s, d0);
    }
  }
  const double points = candidates / kPi;
  // A growing vector holds up to twice its points while it moves them.
  check_memory(2.0 * points * sizeof(Eigen::Vector3d),
               "a simulated scan of about " + std::to_string(static_cast<long long>(points)) +
                   " points (density " + format_significant(o.density_per_m2) + " per m2)");
}

// Points of internode u seen from scanner s at reference distance d0.
void scan_internode(const TreeGraph& t, NodeId u, const OccluderGrid& grid,
                    const Eigen::Vector3d& s, double d0, const ScanOptions& o, std::mt19937_64& rng,
                    PointSet& out) {
  const Eigen::Vector3d a = t.start(u), axis = (t.end(u) - a).normalized();
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  const double r = t.radius(u), len = t.length(u);
  const double boost = near_boost(t, u, s, d0);
  std::poisson_distribution<long> count(o.density_per_m2 * 2 * kPi * r * len * boost);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, o.range_noise_m);
  for (long k = count(rng); k > 0; --k) {
    const double phi = 2 * kPi * unit(rng), along = len * unit(rng), keep = unit(rng);
    const Eigen::Vector3d n = std::cos(phi) * e1 + std::sin(phi) * e2;
    const Eigen::Vector3d p = a + along * axis + r * n;
    const Eigen::Vector3d to_s = s - p;
    const double dist = to_s.norm(), cos_inc = n.dot(to_s) / dist;
    if (cos_inc <= 0.0 || keep * boost > cos_inc * (d0 / dist) * (d0 / dist)) continue;
    if (occluded(t, grid, u, s, p)) continue;
    out.points.push_back(p - to_s / dist * noise(rng));
  }
}

}  // namespace

std::vector<Eigen::Vector3d> scanner_positions(const TreeGraph& t, const ScanOptions& o) {
  if (t.empty()) return {};
  double height = 0.0;
  for (NodeId u = 0; u < t.size(); ++u) height = std::max(height, t.end(u).z() - t.start(0).z());
  const double radius = std::max(1.0, o.distance_factor * height);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < o.scanners; ++k) {
    const double angle = 2 * kPi * k / o.scanners + 0.3;  // off the axes the test trees use
    out.push_back(t.start(0) + Eigen::Vector3d(radius * std::cos(angle), radius * std::sin(angle),
                                               o.scanner_height_m));
  }
  return out;
}

void ScanOptions::validate() const {
  if (scanners < 1) throw ValueError("scan: scanners must be >= 1 (one scanner position at least)");
  if (!(density_per_m2 > 0.0) || !(distance_factor > 0.0)) {
    throw ValueError("scan: density_per_m2 and distance_factor must be positive");
  }
  if (!(range_noise_m >= 0.0)) throw ValueError("scan: range_noise_m must not be negative");
}

PointSet simulate_scan(const TreeGraph& t, const ScanOptions& o, std::mt19937_64& rng) {
  o.validate();
  PointSet out;
  const std::vector<Eigen::Vector3d> scanners = scanner_positions(t, o);
  check_scan_memory(t, scanners, o);
  for (const Eigen::Vector3d& s : scanners) {
    const double d0 = (s - t.start(0)).head<2>().norm();
    const OccluderGrid grid(t, o, s);
    for (NodeId u = 0; u < t.size(); ++u) {
      if (scanned(t, u, o)) scan_internode(t, u, grid, s, d0, o, rng, out);
    }
  }
  return out;
}

}  // namespace fspm::scans
