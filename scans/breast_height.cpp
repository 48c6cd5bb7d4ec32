#include "scans/breast_height.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

namespace fspm::scans {
namespace {

std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

std::int64_t cell_key(std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xFFFFFFFF); }

// Label of each slice point: its connected group of occupied grid cells.
std::vector<std::uint32_t> stem_labels(const std::vector<Eigen::Vector2d>& xy, double link_m) {
  std::unordered_map<std::int64_t, std::uint32_t> cells;
  std::vector<std::uint32_t> cell_of(xy.size());
  for (std::size_t i = 0; i < xy.size(); ++i) {
    const auto cx = static_cast<std::int64_t>(std::floor(xy[i].x() / link_m));
    const auto cy = static_cast<std::int64_t>(std::floor(xy[i].y() / link_m));
    cell_of[i] =
        cells.try_emplace(cell_key(cx, cy), static_cast<std::uint32_t>(cells.size())).first->second;
  }
  std::vector<std::uint32_t> parent(cells.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const auto& [key, id] : cells) {
    const std::int64_t cx = key >> 32;
    const auto cy = static_cast<std::int64_t>(static_cast<std::int32_t>(key & 0xFFFFFFFF));
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(cell_key(cx + dx, cy + dy));
        if (it != cells.end()) parent[find(parent, id)] = find(parent, it->second);
      }
    }
  }
  for (std::uint32_t& c : cell_of) c = find(parent, c);
  return cell_of;
}

}  // namespace

BreastHeightStem stem_slice(const PointSet& ps, const std::vector<char>& on_trunk, double ground_z,
                            double low_m, double high_m, const BreastHeightOptions& o) {
  BreastHeightStem out;
  std::vector<Eigen::Vector2d> xy;
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const double h = ps.points[i].z() - ground_z;
    if (on_trunk[i] && h >= low_m && h <= high_m) {
      xy.push_back(ps.points[i].head<2>());
    }
  }
  out.slice_points = xy.size();
  if (xy.size() < o.min_points) return out;
  out.circle = fit_circle_kasa(xy);
  out.compact = out.circle && out.circle->rms_m <= 0.2 * out.circle->radius_m + 0.005 &&
                2.0 * out.circle->radius_m <= o.max_diameter_m;
  return out;
}

std::vector<std::size_t> stems_at_base(const PointSet& ps, double ground_z,
                                       const BreastHeightOptions& o) {
  std::vector<Eigen::Vector2d> xy;
  for (const Eigen::Vector3d& p : ps.points) {
    const double h = p.z() - ground_z;
    if (h >= o.base_low_m && h <= o.base_high_m) xy.push_back(p.head<2>());
  }
  std::unordered_map<std::uint32_t, std::size_t> size;
  for (std::uint32_t l : stem_labels(xy, o.link_m)) ++size[l];
  std::size_t largest = 0;
  for (const auto& [l, n] : size) largest = std::max(largest, n);
  std::vector<std::size_t> out;
  for (const auto& [l, n] : size) {
    if (n >= o.min_points && 5 * n >= largest) out.push_back(n);
  }
  std::sort(out.rbegin(), out.rend());
  return out;
}

}  // namespace fspm::scans
