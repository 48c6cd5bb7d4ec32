#include "scans/vertical_plane.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <vector>

namespace fspm::scans {
namespace {

struct Slab {
  double nx = 0.0, ny = 0.0;  // horizontal unit normal
  double d_lo = 0.0;          // the slab is d_lo <= n . (x, y) < d_lo + thickness
};

// The above-ground points, an even subsample of them, relative to the first point.
std::vector<Eigen::Vector3d> voters(const PointSet& ps, const VerticalPlaneOptions& o) {
  double z0 = INFINITY;
  for (const Eigen::Vector3d& p : ps.points) z0 = std::min(z0, p.z());
  std::vector<Eigen::Vector3d> above;
  for (const Eigen::Vector3d& p : ps.points) {
    if (p.z() > z0 + o.ground_m) above.push_back(p - ps.points[0]);
  }
  const std::size_t stride = std::max<std::size_t>(1, above.size() / o.max_points);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < above.size(); i += stride) out.push_back(above[i]);
  return out;
}

// Flat area of one slab: the cells where the slab holds min_flatness of the near points.
VerticalPlane flat_part(const std::vector<Eigen::Vector3d>& pts, const Slab& s,
                        const VerticalPlaneOptions& o) {
  std::unordered_map<std::int64_t, std::pair<std::size_t, std::size_t>> cells;  // slab, near
  const double margin = o.neighbourhood_m - 0.5 * o.thickness_m;
  for (const Eigen::Vector3d& p : pts) {
    const double d = s.nx * p.x() + s.ny * p.y();
    if (d < s.d_lo - margin || d >= s.d_lo + o.thickness_m + margin) continue;
    const double u = -s.ny * p.x() + s.nx * p.y();
    const auto cu = static_cast<std::int64_t>(std::floor(u / o.cell_m));
    const auto cz = static_cast<std::int64_t>(std::floor(p.z() / o.cell_m));
    auto& [slab, near] = cells[cu * 4000037 + cz];
    ++near;
    slab += d >= s.d_lo && d < s.d_lo + o.thickness_m;
  }
  VerticalPlane v;
  std::size_t flat_points = 0;
  for (const auto& [cell, counts] : cells) {
    if (counts.first < 3 || counts.first < o.min_flatness * counts.second) continue;
    v.area_m2 += o.cell_m * o.cell_m;
    flat_points += counts.first;
  }
  v.share = static_cast<double>(flat_points) / static_cast<double>(pts.size());
  return v;
}

}  // namespace

std::optional<VerticalPlane> largest_vertical_plane(const PointSet& ps,
                                                    const VerticalPlaneOptions& o) {
  if (ps.points.empty()) return std::nullopt;
  const std::vector<Eigen::Vector3d> pts = voters(ps, o);
  if (pts.empty()) return std::nullopt;
  double reach = 0.0;
  for (const Eigen::Vector3d& p : pts) reach = std::max(reach, p.head<2>().norm());
  // Offsets in half-slab bins; a slab is two neighbouring bins, so a plane is not split in two.
  const double bin_m = 0.5 * o.thickness_m;
  const auto bins = static_cast<std::size_t>(2.0 * reach / bin_m) + 2;
  std::vector<std::size_t> votes(bins), order;
  std::optional<VerticalPlane> best;
  for (int k = 0; k < o.directions; ++k) {
    const double theta = std::numbers::pi * k / o.directions;
    const Slab base{std::cos(theta), std::sin(theta), 0.0};
    std::fill(votes.begin(), votes.end(), 0);
    for (const Eigen::Vector3d& p : pts) {
      const double d = base.nx * p.x() + base.ny * p.y() + reach;
      ++votes[std::min(bins - 1, static_cast<std::size_t>(d / bin_m))];
    }
    // The fullest slabs that are peaks of the votes (a trunk's neighbouring slabs are not).
    const auto slab_votes = [&](std::size_t b) { return votes[b] + votes[b + 1]; };
    order.clear();
    for (std::size_t b = 0; b + 1 < bins; ++b) {
      const bool peak = (b == 0 || slab_votes(b) >= slab_votes(b - 1)) &&
                        (b + 2 >= bins || slab_votes(b) > slab_votes(b + 1));
      if (peak && slab_votes(b) >= 3) order.push_back(b);
    }
    const std::size_t fullest = std::min<std::size_t>(o.candidates, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(fullest),
                      order.end(),
                      [&](std::size_t a, std::size_t b) { return slab_votes(a) > slab_votes(b); });
    for (std::size_t c = 0; c < fullest; ++c) {
      Slab s = base;
      s.d_lo = static_cast<double>(order[c]) * bin_m - reach;
      const VerticalPlane v = flat_part(pts, s, o);
      if (v.area_m2 > 0.0 && (!best || v.area_m2 > best->area_m2)) best = v;
    }
  }
  return best;
}

}  // namespace fspm::scans
