#include "scan_decoding/cluster_texturing.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <string>

#include "fspm/error.hpp"
#include "scan_decoding/hull_geometry.hpp"

namespace fspm::scan_decoding {

void TextureOptions::validate() const {
  if (!(max_thickness_ratio >= 1.0) || !std::isfinite(max_thickness_ratio)) {
    throw ValueError("texturing: max_thickness_ratio (of similar patches) must be finite and >= 1");
  }
  if (!(max_angle_deg > 0.0 && max_angle_deg <= 180.0)) {
    throw ValueError("texturing: max_angle_deg (of similar patches) must be within (0, 180]");
  }
  if (!(fit_tolerance >= 0.0) || !std::isfinite(fit_tolerance)) {
    throw ValueError("texturing: fit_tolerance must be finite and >= 0");
  }
  if (max_depth < 0 || max_patches_per_cluster == 0) {
    throw ValueError("texturing: max_depth must be >= 0 and max_patches_per_cluster >= 1");
  }
  if (!(min_scale_ratio >= 0.0 && min_scale_ratio <= 1.0)) {
    throw ValueError("texturing: min_scale_ratio (of a docked patch) must be within [0, 1]");
  }
  if (!(max_scale > 0.0)) {
    throw ValueError("texturing: max_scale must be positive");
  }
}

namespace {

// Further seeds drawn in a row that place nothing before a cluster is left short of its length.
constexpr int kMaxSeedMisses = 16;

struct Pending {
  Docking docking;
  std::uint32_t parent = kNoPlacement;
  std::uint32_t docking_index = 0;
  int depth = 0;
  double parent_scale = 0.0;
};

// Rotation taking the patch's v_r onto the docking direction, rolled about it by `roll_rad`.
Eigen::Matrix3d docking_rotation(const Eigen::Vector3d& v_r, const Eigen::Vector3d& v_d,
                                 double roll_rad) {
  const Eigen::Matrix3d align =
      Eigen::Quaterniond::FromTwoVectors(v_r, v_d).normalized().toRotationMatrix();
  return Eigen::AngleAxisd(roll_rad, v_d).toRotationMatrix() * align;
}

// How far the ray along the docking direction goes before it leaves the hull: the last crossing
// from the seed point, which may lie outside the hull; the first from a docking point inside it.
// 0 when the ray does not reach the hull. The same for every patch tried at the position.
double hull_reach_m(const scans::ClusterHull& hull, const Pending& p) {
  const std::vector<double> ts = ray_hull_crossings(hull, p.docking.position, p.docking.direction);
  if (ts.empty()) return 0.0;
  return p.parent == kNoPlacement ? ts.back() : ts.front();
}

// Patch fitting: the scale at which the patch ends where the ray leaves the hull (`reach_m`),
// never larger than its parent's nor than max_scale (the species' sizes). 0 when the ray does not
// reach the hull.
double fitted_scale(double reach_m, const Pending& p, const Patch& patch, double max_scale) {
  if (!(reach_m > 0.0) || !(patch.length_m > 0.0)) return 0.0;
  const double scale = std::min(reach_m / patch.length_m, max_scale);
  return p.parent == kNoPlacement ? scale : std::min(scale, p.parent_scale);
}

// How many of the patch's docking points, placed by `rotation` and `scale` at the docking
// position, lie inside the hull: where texturing can go on.
std::size_t dockings_inside(const scans::ClusterHull& hull, const Pending& p, const Patch& patch,
                            const Eigen::Matrix3d& rotation, double scale) {
  std::size_t n = 0;
  for (const DockingPoint& dp : patch.dockings) {
    n += inside_hull(hull, p.docking.position + scale * (rotation * dp.position));
  }
  return n;
}

// Pirk 3.4: of the patches that fit eq. 3.3 equally well, the one that "corresponds best to the
// local geometry of the cluster": the most docking points inside the hull once fitted, so that
// texturing goes on until the cluster is filled (Figure 3.7) and patches without docking points
// (which end it) are taken where nothing more fits. Ties are drawn with the generator.
std::uint32_t geometric_choice(const scans::ClusterHull& hull, const Pending& p, double reach_m,
                               const SpeciesLibrary& library,
                               const std::vector<std::uint32_t>& best, double roll_rad,
                               double max_scale, std::mt19937_64& rng) {
  std::vector<std::uint32_t> most;
  std::size_t most_inside = 0;
  for (const std::uint32_t k : best) {
    const Patch& patch = library.patches[k];
    const double scale = fitted_scale(reach_m, p, patch, max_scale);
    const std::size_t inside =
        scale > 0.0 ? dockings_inside(
                          hull, p, patch,
                          docking_rotation(patch.direction, p.docking.direction, roll_rad), scale)
                    : 0;
    if (inside > most_inside || most.empty()) most.clear(), most_inside = inside;
    if (inside == most_inside) most.push_back(k);
  }
  std::uniform_int_distribution<std::size_t> pick(0, most.size() - 1);
  return most[pick(rng)];
}

}  // namespace

double patch_fit(double thickness_r, double thickness_d, const Eigen::Vector3d& v_r,
                 const Eigen::Vector3d& v_d) {
  // Pirk eq. 3.3
  return std::max(thickness_r, thickness_d) / std::min(thickness_r, thickness_d) * v_r.dot(v_d);
}

std::vector<std::uint32_t> similar_patches(const SpeciesLibrary& library, const Docking& docking,
                                           const TextureOptions& options) {
  const double min_cos = std::cos(options.max_angle_deg * std::numbers::pi / 180.0);
  std::vector<std::uint32_t> out;
  for (std::uint32_t k = 0; k < library.patches.size(); ++k) {
    const Patch& p = library.patches[k];
    const double ratio =
        std::max(p.thickness, docking.thickness) / std::min(p.thickness, docking.thickness);
    if (ratio <= options.max_thickness_ratio && p.direction.dot(docking.direction) >= min_cos) {
      out.push_back(k);
    }
  }
  return out;
}

std::vector<std::uint32_t> best_fitting_patches(const SpeciesLibrary& library,
                                                const std::vector<std::uint32_t>& candidates,
                                                const Docking& docking,
                                                const TextureOptions& options) {
  std::vector<double> miss(candidates.size());
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Patch& p = library.patches[candidates[k]];
    miss[k] =
        std::abs(patch_fit(p.thickness, docking.thickness, p.direction, docking.direction) - 1.0);
    best = std::min(best, miss[k]);
  }
  std::vector<std::uint32_t> out;
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    if (miss[k] <= best + options.fit_tolerance) out.push_back(candidates[k]);
  }
  return out;
}

Docking seed_docking(const scans::ClusterModel& model, std::size_t cluster) {
  const scans::ClusterHull& hull = model.clusters[cluster];
  Docking d;
  d.position = model.skeleton.end(hull.seed_node);
  const Eigen::Vector3d to_centroid = hull_centroid(hull) - d.position;
  const Eigen::Vector3d heading = model.skeleton.direction(hull.seed_node);
  if (to_centroid.norm() > 1e-12) {
    d.direction = to_centroid.normalized();
  } else if (heading.norm() > 1e-12) {
    d.direction = heading.normalized();
  }
  d.thickness = 1.0;
  return d;
}

namespace {

// The texturing of one cluster in progress: the placed patches and their branch length.
struct ClusterTexture {
  const scans::ClusterHull& hull;
  const SpeciesLibrary& library;
  const TextureOptions& options;
  std::uint32_t cluster = 0;
  std::vector<PlacedPatch> placed;
  double branch_length_m = 0.0;
  // The branch length to texture up to (infinite: Pirk's texturing alone). A patch that would
  // pass it by more than it falls short without the patch is not placed, so that many small
  // clusters do not each overshoot by most of a patch.
  double until_m = std::numeric_limits<double>::infinity();
};

// Patch selection and fitting at one docking position (Pirk 3.4); the placed patch's docking
// points inside the hull are queued. Nothing is placed where no patch fits.
void dock(ClusterTexture& t, const Pending& p, std::deque<Pending>& queue, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> roll(0.0, 2.0 * std::numbers::pi);
  std::vector<std::uint32_t> s_s = similar_patches(t.library, p.docking, t.options);
  if (s_s.empty() && p.parent == kNoPlacement) {
    for (std::uint32_t k = 0; k < t.library.patches.size(); ++k) s_s.push_back(k);
  }
  const std::vector<std::uint32_t> best =
      best_fitting_patches(t.library, s_s, p.docking, t.options);
  if (best.empty()) return;
  const double roll_rad = roll(rng);
  const double reach_m = hull_reach_m(t.hull, p);
  const std::uint32_t chosen =
      geometric_choice(t.hull, p, reach_m, t.library, best, roll_rad, t.options.max_scale, rng);
  const Patch& patch = t.library.patches[chosen];
  const double scale = fitted_scale(reach_m, p, patch, t.options.max_scale);
  if (!(scale > 0.0) ||
      (p.parent != kNoPlacement && scale < t.options.min_scale_ratio * p.parent_scale)) {
    return;
  }
  const double after_m = t.branch_length_m + scale * patch.internode_length_m;
  if (after_m - t.until_m > t.until_m - t.branch_length_m) return;
  PlacedPatch pp;
  pp.patch = chosen;
  pp.cluster = t.cluster;
  pp.parent = p.parent;
  pp.docking = p.docking_index;
  pp.rotation = docking_rotation(patch.direction, p.docking.direction, roll_rad);
  pp.scale = scale;
  pp.translation = p.docking.position;
  pp.fit = patch_fit(patch.thickness, p.docking.thickness, patch.direction, p.docking.direction);
  pp.depth = p.depth;
  const auto index = static_cast<std::uint32_t>(t.placed.size());
  t.placed.push_back(pp);
  t.branch_length_m += scale * patch.internode_length_m;
  if (p.depth >= t.options.max_depth) return;
  for (std::uint32_t k = 0; k < patch.dockings.size(); ++k) {
    const DockingPoint& dp = patch.dockings[k];
    Pending next;
    next.docking.position = pp.to_world(dp.position);
    next.docking.direction = (pp.rotation * dp.direction).normalized();
    next.docking.thickness = dp.thickness;
    next.parent = index;
    next.docking_index = k;
    next.depth = p.depth + 1;
    next.parent_scale = scale;
    if (inside_hull(t.hull, next.docking.position)) queue.push_back(next);
  }
}

// Docks from `start` and then from every docking point it opens, breadth first, until all are
// used ("the cluster geometry is filled", Pirk 3.4), the cluster has its most patches, or the
// placed branch length reaches `until_length_m`.
void texture_from(ClusterTexture& t, const Pending& start, double until_length_m,
                  std::mt19937_64& rng) {
  std::deque<Pending> queue{start};
  while (!queue.empty() && t.placed.size() < t.options.max_patches_per_cluster &&
         t.branch_length_m < until_length_m) {
    const Pending p = queue.front();
    queue.pop_front();
    dock(t, p, queue, rng);
  }
}

// A point drawn uniformly inside the hull (rejection in its box); a hull vertex when 64 draws
// all miss (a thin hull).
Eigen::Vector3d point_inside(const scans::ClusterHull& hull, std::mt19937_64& rng) {
  Eigen::Vector3d lo = hull.vertices[0], hi = hull.vertices[0];
  for (const Eigen::Vector3d& v : hull.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 64; ++k) {
    const Eigen::Vector3d q(lo.x() + u(rng) * (hi.x() - lo.x()),
                            lo.y() + u(rng) * (hi.y() - lo.y()),
                            lo.z() + u(rng) * (hi.z() - lo.z()));
    if (inside_hull(hull, q)) return q;
  }
  std::uniform_int_distribution<std::size_t> pick(0, hull.vertices.size() - 1);
  return hull.vertices[pick(rng)];
}

}  // namespace

std::vector<PlacedPatch> texture_cluster(const scans::ClusterModel& model, std::size_t cluster,
                                         const SpeciesLibrary& library,
                                         const TextureOptions& options, std::mt19937_64& rng) {
  const scans::ClusterHull& hull = model.clusters[cluster];
  ClusterTexture t{hull, library, options, static_cast<std::uint32_t>(cluster), {}, 0.0};
  if (hull.triangles.empty()) return t.placed;
  const Pending seed{seed_docking(model, cluster)};
  const bool match = options.match_branch_length && hull.branch_length_m > 0.0;
  const double until_m = match ? hull.branch_length_m : std::numeric_limits<double>::infinity();
  t.until_m = until_m;
  texture_from(t, seed, until_m, rng);
  if (!match) return t.placed;
  // Beyond Pirk: texturing ends at the branch length the scan showed in the cluster, breadth
  // first, so a large cluster's finest docking points may stay empty. Where the docking points
  // are used up before it (one branchlet's worth of patches per seed), further branchlets start
  // at the seed point, each towards a point drawn inside the hull, until it is reached.
  int misses = 0;
  while (t.branch_length_m < hull.branch_length_m &&
         t.placed.size() < options.max_patches_per_cluster && misses < kMaxSeedMisses) {
    Pending extra = seed;
    const Eigen::Vector3d to = point_inside(hull, rng) - seed.docking.position;
    if (to.norm() > 1e-12) extra.docking.direction = to.normalized();
    const std::size_t before = t.placed.size();
    texture_from(t, extra, hull.branch_length_m, rng);
    misses = t.placed.size() == before ? misses + 1 : 0;
  }
  return t.placed;
}

std::vector<PlacedPatch> texture_clusters(const scans::ClusterModel& model,
                                          const SpeciesLibrary& library,
                                          const TextureOptions& options, std::mt19937_64& rng) {
  options.validate();
  if (library.patches.empty()) throw ValueError("the species library has no patches");
  std::vector<PlacedPatch> all;
  for (std::size_t c = 0; c < model.clusters.size(); ++c) {
    if (model.clusters[c].seed_node >= model.skeleton.size()) {
      throw ValueError("cluster " + std::to_string(c) + " hangs at skeleton node " +
                       std::to_string(model.clusters[c].seed_node) + ", but the skeleton has " +
                       std::to_string(model.skeleton.size()) + " nodes");
    }
    std::vector<PlacedPatch> placed = texture_cluster(model, c, library, options, rng);
    const auto offset = static_cast<std::uint32_t>(all.size());
    for (PlacedPatch& p : placed) {
      if (p.parent != kNoPlacement) p.parent += offset;
      all.push_back(p);
    }
  }
  return all;
}

}  // namespace fspm::scan_decoding
