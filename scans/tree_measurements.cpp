#include "scans/tree_measurements.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"
#include "scans/allometry.hpp"
#include "scans/crown_base.hpp"
#include "scans/point_origin.hpp"
#include "scans/segment_distance.hpp"
#include "scans/vertical_plane.hpp"

namespace fspm::scans {
namespace {

std::string metres(double v) { return fmt::format("{:.3f} m", v); }

// Two or more separate codominant stems at breast height, together no thicker than the stem at
// the foot: no single DBH (foresters measure each stem of a fork below breast height as a tree);
// their diameters are reported.
bool fork_at_breast_height(const PointSet& ps, const std::vector<char>& on_trunk, double z0,
                           const BreastHeightOptions& b, TreeMeasurements& m) {
  const std::vector<StemSection> stems = stems_at_breast_height(ps, z0, b);
  if (stems.size() < 2) return false;
  // Stems thicker together than the stem at the foot are no fork of it (branches crossing the
  // slice that happen to lie on circles; Shinozaki et al. 1964's pipe model).
  const StemSection foot = stem_slice(ps, on_trunk, z0, b.stem_low_m, b.stem_high_m, b);
  if (foot.compact) {
    double area = 0.0;
    for (const StemSection& s : stems) area += s.circle->radius_m * s.circle->radius_m;
    const double limit = b.max_fork_to_foot * foot.circle->radius_m;
    if (area > limit * limit) return false;
  }
  std::vector<std::string> d;
  for (const StemSection& s : stems) {
    m.breast_height_stems_m.push_back(2.0 * s.circle->radius_m);
    d.push_back(metres(2.0 * s.circle->radius_m));
  }
  m.tree_found = true;
  m.warnings.push_back(fmt::format(
      "{} separate stems {:.1f}-{:.1f} m above the lowest point (diameters {}): the tree forks "
      "below breast height, or the cloud holds several trees; no dbh; each stem is measured as "
      "a tree (breast_height_stems_m)",
      stems.size(), b.slice_low_m, b.slice_high_m, fmt::join(d, ", ")));
  return true;
}

// The trunk points at breast height lie on no circle: a stem at the foot makes it a tree whose
// stem the slice does not show as one circle; none, no tree.
void not_a_stem(const PointSet& ps, const std::vector<char>& on_trunk, double z0,
                const BreastHeightOptions& b, const StemSection& s, const std::string& slice,
                TreeMeasurements& m) {
  const StemSection foot = stem_slice(ps, on_trunk, z0, b.stem_low_m, b.stem_high_m, b);
  m.tree_found = foot.compact;
  const std::string fit =
      s.circle ? fmt::format("median residual {} for a radius of {}, {} of 12 sectors covered",
                             metres(s.median_residual_m), metres(s.circle->radius_m), s.sectors)
               : std::string("no circle");
  if (foot.compact) {
    m.warnings.push_back(fmt::format(
        "no single trunk at breast height: the {} {} do not lie on one circle ({}), but a stem "
        "of {} stands {:.1f}-{:.1f} m above the lowest point: branches, leaves or a fork at "
        "breast height; no dbh; check the slice or measure the stem",
        s.points, slice, fit, metres(2.0 * foot.circle->radius_m), b.stem_low_m, b.stem_high_m));
  } else {
    m.warnings.push_back(fmt::format(
        "no vertical trunk found: the {} {} do not lie on a circle of at most {} ({}), nor do "
        "those {:.1f}-{:.1f} m above it (a wall, a hedge, a crown down to the ground?)",
        s.points, slice, metres(b.max_diameter_m), fit, b.stem_low_m, b.stem_high_m));
  }
}

void measure_stem(const PointSet& ps, const std::vector<char>& on_trunk, double z0,
                  const MeasureOptions& o, TreeMeasurements& m) {
  const BreastHeightOptions& b = o.breast_height;
  const std::vector<std::size_t> stems = stems_at_base(ps, z0, b);
  m.stems = stems.size();
  if (stems.size() > 1) {
    m.warnings.push_back(fmt::format(
        "{} separate stems {:.1f}-{:.1f} m above the lowest point (points: {}): several trees "
        "or a stem forked below; the measurements take them as one tree; crop the cloud to one "
        "tree",
        stems.size(), b.base_low_m, b.base_high_m, fmt::join(stems, ", ")));
  }
  const StemSection s = stem_slice(ps, on_trunk, z0, b.slice_low_m, b.slice_high_m, b);
  m.breast_height_points = s.points;
  const std::string slice = fmt::format("trunk points {:.1f}-{:.1f} m above the lowest point",
                                        b.slice_low_m, b.slice_high_m);
  if (s.points < b.min_points) {
    m.tree_found = true;  // nothing to judge the stem by (an airborne scan, a short plant)
    m.warnings.push_back(fmt::format(
        "only {} {} (at least {} needed): no trunk diameter; scan the stem or measure it", s.points,
        slice, b.min_points));
    return;
  }
  if (fork_at_breast_height(ps, on_trunk, z0, b, m)) return;
  if (!s.compact) {
    not_a_stem(ps, on_trunk, z0, b, s, slice, m);
    return;
  }
  m.tree_found = true;
  m.dbh_m = 2.0 * s.circle->radius_m;
}

// A point in a stem slice within the radius of an order-0 cylinder (plus a quarter of it, at
// least 2 cm, for scanner noise and misregistered scans) of its axis lies on the stem's surface
// even when its nearest segment is a branch's first one: at a fork that segment starts on the
// trunk's axis and takes the stem's ring points on its side, which leaves the trunk an arc that
// fits no circle (the terrestrial scan of a lodgepole pine in examples/scans/ forks at 1.27 m).
void add_stem_surface_points(const PointSet& ps, const std::vector<QsmCylinder>& cylinders,
                             double z_low, double z_high, std::vector<char>& on_trunk) {
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    const Eigen::Vector3d& p = ps.points[i];
    if (on_trunk[i] || p.z() < z_low || p.z() > z_high) continue;
    for (const QsmCylinder& c : cylinders) {
      if (c.order != 0) continue;
      const double reach = c.radius_m + std::max(0.25 * c.radius_m, 0.02);
      if (segment_distance(p, p, c.start, c.start + c.length_m * c.axis) <= reach) {
        on_trunk[i] = 1;
        break;
      }
    }
  }
}

void measure_crown(const PointSet& ps, const TreeGraph& t, double z0,
                   const std::vector<std::uint32_t>& cylinder_of_point, const MeasureOptions& o,
                   TreeMeasurements& m) {
  if (const std::optional<double> z =
          crown_base_z(ps, t, cylinder_of_point, m.cylinders, o.min_branch_length_m)) {
    m.crown_base_m = *z - z0;
  }
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
  const double from = z0 + m.crown_base_m.value_or(0.0);
  for (const Eigen::Vector3d& p : ps.points) {
    if (p.z() >= from) lo = lo.cwiseMin(p.head<2>()), hi = hi.cwiseMax(p.head<2>());
  }
  m.crown_width_m = lo.allFinite() ? 0.5 * ((hi - lo).x() + (hi - lo).y()) : 0.0;
}

// The cylinders and their numbers; returns the cylinder (skeleton node) of every point.
std::vector<std::uint32_t> measure_cylinders(const PointSet& ps, const TreeGraph& t,
                                             const MeasureOptions& o, TreeMeasurements& m) {
  QsmCylinders q = fit_qsm_cylinders(ps, t);
  m.woody_volume_m3 = cylinders_volume_m3(q.cylinders);
  std::size_t explained = 0;
  for (double d : q.surface_distance_m) explained += d <= o.explained_tolerance_m;
  m.points_explained_fraction = static_cast<double>(explained) / ps.points.size();
  for (NodeId u = 0; u < t.size(); ++u) {
    const std::size_t order = t.order(u);
    if (m.branches_per_order.size() <= order) {
      m.branches_per_order.resize(order + 1, 0);
      m.branch_length_per_order_m.resize(order + 1, 0.0);
    }
    const NodeId p = t.parent(u);
    if (p == kNoNode || t.order(p) != t.order(u)) ++m.branches_per_order[order];
    m.branch_length_per_order_m[order] += t.length(u);
  }
  m.cylinders = std::move(q.cylinders);
  return std::move(q.cylinder_of_point);
}

// A flat vertical surface of many square metres is a wall or a facade (scans/vertical_plane.hpp):
// without a stem at breast height the scan is a building, not a tree; with one, a building stands
// beside the tree and widens its crown.
void judge_walls(const PointSet& ps, const MeasureOptions& o, TreeMeasurements& m) {
  const std::optional<VerticalPlane> wall = largest_vertical_plane(ps, o.wall);
  if (!wall || wall->area_m2 < o.min_wall_area_m2) return;
  const std::string what = fmt::format(
      "{:.0f} m2 of the points lie on one flat vertical surface (a wall or a facade; a tree's "
      "largest is a few m2)",
      wall->area_m2);
  if (m.dbh_m) {
    m.warnings.push_back(what + ": cut the building out of the scan before measuring the crown");
    return;
  }
  m.tree_found = false;
  m.warnings.insert(m.warnings.begin(),
                    what +
                        " and no stem stands at breast height: a building, not a tree; cut "
                        "the tree out of the scan");
}

}  // namespace

TreeMeasurements measure_tree(const PointSet& absolute, const TreeGraph& skeleton,
                              const MeasureOptions& o) {
  if (absolute.points.empty()) throw ValueError("measuring a tree needs points");
  if (skeleton.empty()) throw ValueError("measuring a tree needs a skeleton");
  const Eigen::Vector3d origin = point_set_origin(absolute);
  const PointSet ps = relative_to(absolute, origin);
  TreeGraph t = skeleton;
  translate_tree(t, -origin);
  double z0 = ps.points[0].z(), z1 = z0;
  for (const Eigen::Vector3d& p : ps.points) z0 = std::min(z0, p.z()), z1 = std::max(z1, p.z());
  TreeMeasurements m;
  m.height_m = z1 - z0;
  const std::vector<std::uint32_t> cylinder_of_point = measure_cylinders(ps, t, o, m);
  std::vector<char> on_trunk(ps.points.size());  // the point's nearest segment has order 0
  for (std::size_t i = 0; i < ps.points.size(); ++i) {
    on_trunk[i] = m.cylinders[cylinder_of_point[i]].order == 0;
  }
  const BreastHeightOptions& b = o.breast_height;
  add_stem_surface_points(ps, m.cylinders, z0 + std::min(b.stem_low_m, b.slice_low_m),
                          z0 + std::max(b.stem_high_m, b.slice_high_m), on_trunk);
  measure_stem(ps, on_trunk, z0, o, m);
  measure_crown(ps, t, z0, cylinder_of_point, o, m);
  for (QsmCylinder& c : m.cylinders) c.start += origin;
  if (m.dbh_m && *m.dbh_m > o.max_dbh_per_height * m.height_m) {
    m.warnings.push_back(fmt::format(
        "a trunk diameter of {} is implausible for a height of {} (more than {:.0f} % of it): "
        "check the breast-height slice for branches, leaves or other objects",
        metres(*m.dbh_m), metres(m.height_m), 100.0 * o.max_dbh_per_height));
  }
  judge_walls(ps, o, m);
  return m;
}

}  // namespace fspm::scans
