#include "scans/breast_height.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
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

std::vector<Eigen::Vector2d> horizontal(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector2d> xy(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) xy[i] = points[i].head<2>();
  return xy;
}

struct StemAxis {
  Eigen::Vector2d lean = Eigen::Vector2d::Zero();  // horizontal drift per metre of height
  std::optional<Circle> mid;                  // the horizontal circle at the points' mean height
  std::optional<double> radius_change_per_m;  // from the lower half's circle to the upper's
};

// The stem's axis from the robust circles of the slice's lower and upper halves, whose centres
// lie on the axis; the upper circle starts from the lower one, so that both follow the same stem
// where a group holds two. No lean when a half has too few points for a circle.
StemAxis stem_axis(const std::vector<Eigen::Vector3d>& points) {
  double mid = 0.0;
  for (const Eigen::Vector3d& p : points) mid += p.z();
  mid /= static_cast<double>(points.size());
  std::vector<Eigen::Vector3d> half[2];
  for (const Eigen::Vector3d& p : points) half[p.z() >= mid].push_back(p);
  constexpr std::size_t kMinHalf = 10;
  StemAxis out;
  if (half[0].size() < kMinHalf || half[1].size() < kMinHalf) return out;
  std::optional<RobustCircle> c[2];
  double z[2] = {0.0, 0.0};
  for (int h = 0; h < 2; ++h) {
    c[h] = fit_circle_robust(horizontal(half[h]), {},
                             h ? std::optional<Circle>(c[0]->circle) : std::nullopt);
    if (!c[h]) return out;
    for (const Eigen::Vector3d& p : half[h]) z[h] += p.z();
    z[h] /= static_cast<double>(half[h].size());
  }
  if (!(z[1] - z[0] > 1e-6)) return out;
  out.lean = (c[1]->circle.centre - c[0]->circle.centre) / (z[1] - z[0]);
  Circle m;
  m.centre = c[0]->circle.centre + (mid - z[0]) * out.lean;
  m.radius_m = 0.5 * (c[0]->circle.radius_m + c[1]->circle.radius_m);
  out.mid = m;
  out.radius_change_per_m = (c[1]->circle.radius_m - c[0]->circle.radius_m) / (z[1] - z[0]);
  return out;
}

// The points in the plane across the axis of direction (lean, 1) through their mean, in an
// orthonormal basis of that plane whose origin is the mean; `mean` returns it.
std::vector<Eigen::Vector2d> across_axis(const std::vector<Eigen::Vector3d>& points,
                                         const Eigen::Vector2d& lean, Eigen::Vector3d& mean,
                                         Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  const Eigen::Vector3d a = Eigen::Vector3d(lean.x(), lean.y(), 1.0).normalized();
  e1 = Eigen::Vector3d(a.z(), 0.0, -a.x()).normalized();  // a . e1 = 0
  e2 = a.cross(e1);
  mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  std::vector<Eigen::Vector2d> q(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - mean;
    q[i] = Eigen::Vector2d(d.dot(e1), d.dot(e2));
  }
  return q;
}

bool is_compact(const StemSection& s, const BreastHeightOptions& o) {
  if (!s.circle) return false;
  const double r = s.circle->radius_m;
  return s.median_residual_m <=
             std::min(o.max_residual_share * r, o.max_residual_m) + o.residual_floor_m &&
         static_cast<double>(s.inliers) >= o.min_inlier_share * static_cast<double>(s.points) &&
         s.sectors >= o.min_sectors && 2.0 * r <= o.max_diameter_m && s.lean_deg <= o.max_lean_deg;
}

// The section across the given axis: the points projected onto the plane across it and a
// robust circle there, started from the axis's circle.
StemSection section_across(const std::vector<Eigen::Vector3d>& points, const StemAxis& axis,
                           const BreastHeightOptions& o) {
  StemSection out;
  out.points = points.size();
  out.lean_deg = std::atan(axis.lean.norm()) * 180.0 / std::numbers::pi;
  out.radius_change_per_m = axis.radius_change_per_m;
  Eigen::Vector3d mean, e1, e2;
  const std::vector<Eigen::Vector2d> q = across_axis(points, axis.lean, mean, e1, e2);
  std::optional<Circle> start;
  if (axis.mid) {  // the axis at the mean height lies in the plane across it through the mean
    const Eigen::Vector3d d =
        Eigen::Vector3d(axis.mid->centre.x(), axis.mid->centre.y(), mean.z()) - mean;
    start = Circle{Eigen::Vector2d(d.dot(e1), d.dot(e2)), axis.mid->radius_m, 0.0};
  }
  const std::optional<RobustCircle> c = fit_circle_robust(q, {}, start);
  if (!c) return out;
  out.circle = c->circle;
  const Eigen::Vector3d centre = mean + c->circle.centre.x() * e1 + c->circle.centre.y() * e2;
  out.circle->centre = centre.head<2>();
  out.inliers = c->inliers;
  out.median_residual_m = c->median_residual_m;
  out.sectors = angular_sectors(q, c->inlier, c->circle.centre);
  constexpr int kArcSectors = 36;
  out.longest_arc_deg =
      360.0 / kArcSectors * longest_arc_sectors(q, c->inlier, c->circle.centre, kArcSectors);
  out.inlier = c->inlier;
  out.compact = is_compact(out, o);
  return out;
}

std::vector<Eigen::Vector3d> slice_of(const PointSet& ps, const std::vector<char>* mask,
                                      double ground_z, double low_m, double high_m) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const double h = ps.points[i].z() - ground_z;
    if ((!mask || (*mask)[i]) && h >= low_m && h <= high_m) out.push_back(ps.points[i]);
  }
  return out;
}

// A stem keeps its girth over the slice's height; a ring of branches radiating from the stem
// (a whorl cut by the slice) widens with height as fast as they lean out, and points in a
// ring of a single height band fit no halves. Its surface is one unbroken arc, where branches
// crossing the slice hit a circle at scattered angles.
bool is_cylinder(const StemSection& s, const BreastHeightOptions& o) {
  return s.radius_change_per_m && std::abs(*s.radius_change_per_m) <= o.max_radius_change &&
         s.longest_arc_deg >= o.min_stem_arc_deg;
}

// A section that overlaps a thicker one already kept is part of it (an inner arc of bark or a
// misregistered scan, a branch's foot): two stems' sections are disjoint, up to a touch.
bool overlaps(const StemSection& s, const std::vector<StemSection>& kept) {
  for (const StemSection& k : kept) {
    const double gap =
        (s.circle->centre - k.circle->centre).norm() - k.circle->radius_m - s.circle->radius_m;
    if (gap < -0.5 * std::min(s.circle->radius_m, k.circle->radius_m)) return true;
  }
  return false;
}

// The group split in two by 2-means on the horizontal positions (Lloyd 1982), started from its
// two points farthest apart (the far sides of two touching stems).
std::array<std::vector<Eigen::Vector3d>, 2> two_means(const std::vector<Eigen::Vector3d>& group) {
  const auto farthest = [&](const Eigen::Vector2d& from) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < group.size(); ++i) {
      if ((group[i].head<2>() - from).squaredNorm() >
          (group[best].head<2>() - from).squaredNorm()) {
        best = i;
      }
    }
    return Eigen::Vector2d(group[best].head<2>());
  };
  Eigen::Vector2d c[2];
  c[0] = farthest(group[0].head<2>());
  c[1] = farthest(c[0]);
  std::array<std::vector<Eigen::Vector3d>, 2> part;
  constexpr int kRounds = 20;
  for (int round = 0; round < kRounds; ++round) {
    part[0].clear(), part[1].clear();
    for (const Eigen::Vector3d& p : group) {
      part[(p.head<2>() - c[1]).squaredNorm() < (p.head<2>() - c[0]).squaredNorm()].push_back(p);
    }
    for (int k = 0; k < 2; ++k) {
      if (part[k].empty()) return part;
      c[k].setZero();
      for (const Eigen::Vector3d& p : part[k]) c[k] += p.head<2>();
      c[k] /= static_cast<double>(part[k].size());
    }
  }
  return part;
}

// The compact sections of one group of slice points: the group's and the one of the points off
// it (a second stem beside the first); where the group is no stem, the sections of its two
// halves by 2-means (two touching stems, on which one circle settles between the two).
void group_sections(const std::vector<Eigen::Vector3d>& group, const BreastHeightOptions& o,
                    std::vector<StemSection>& out) {
  const StemSection s = stem_section(group, o);
  if (!s.compact) {
    for (const std::vector<Eigen::Vector3d>& part : two_means(group)) {
      if (part.size() < o.min_points) continue;
      const StemSection t = stem_section(part, o);
      if (t.compact) out.push_back(t);
    }
    return;
  }
  out.push_back(s);
  std::vector<Eigen::Vector3d> rest;
  for (std::size_t i = 0; i < group.size(); ++i) {
    if (!s.inlier[i]) rest.push_back(group[i]);
  }
  if (rest.size() < o.min_points || 10 * rest.size() < 3 * group.size()) return;
  const StemSection t = stem_section(rest, o);
  if (t.compact) out.push_back(t);
}

}  // namespace

StemSection stem_section(const std::vector<Eigen::Vector3d>& points, const BreastHeightOptions& o) {
  if (points.size() < 3) {
    StemSection out;
    out.points = points.size();
    return out;
  }
  // The lean from two half slices is only as good as their circles: on a sparse one-sided arc
  // it is noise that tilts the plane and shrinks the circle. It is kept where it fits the points
  // clearly better (median residual at most 90 % of the vertical axis's).
  const StemAxis axis = stem_axis(points);
  StemSection upright = section_across(
      points, StemAxis{Eigen::Vector2d::Zero(), axis.mid, axis.radius_change_per_m}, o);
  if (axis.lean.isZero()) return upright;
  StemSection leaning = section_across(points, axis, o);
  constexpr double kBetter = 0.9;
  const bool lean_fits =
      leaning.circle &&
      (!upright.circle || leaning.median_residual_m <= kBetter * upright.median_residual_m);
  return lean_fits ? leaning : upright;
}

StemSection stem_slice(const PointSet& ps, const std::vector<char>& on_trunk, double ground_z,
                       double low_m, double high_m, const BreastHeightOptions& o) {
  const std::vector<Eigen::Vector3d> pts = slice_of(ps, &on_trunk, ground_z, low_m, high_m);
  if (pts.size() < o.min_points) {
    StemSection out;
    out.points = pts.size();
    return out;
  }
  return stem_section(pts, o);
}

std::vector<StemSection> stems_at_breast_height(const PointSet& ps, double ground_z,
                                                const BreastHeightOptions& o) {
  const std::vector<Eigen::Vector3d> pts =
      slice_of(ps, nullptr, ground_z, o.slice_low_m, o.slice_high_m);
  const std::vector<std::uint32_t> label = stem_labels(horizontal(pts), o.slice_link_m);
  std::map<std::uint32_t, std::vector<Eigen::Vector3d>> groups;  // ordered: reproducible
  for (std::size_t i = 0; i < pts.size(); ++i) groups[label[i]].push_back(pts[i]);
  std::vector<StemSection> found;
  for (const auto& [l, g] : groups) {
    if (g.size() >= o.min_points) group_sections(g, o, found);
  }
  std::sort(found.begin(), found.end(), [](const StemSection& a, const StemSection& b) {
    return a.circle->radius_m > b.circle->radius_m;
  });
  std::vector<StemSection> out;
  for (StemSection& s : found) {
    if (!out.empty() && s.circle->radius_m < o.codominant_share * out[0].circle->radius_m) break;
    if (is_cylinder(s, o) && !overlaps(s, out)) out.push_back(std::move(s));
  }
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
