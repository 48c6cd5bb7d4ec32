#include "scans/encoder.hpp"

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "scans/allometry.hpp"
#include "scans/cluster_split.hpp"
#include "scans/ground_filter.hpp"
#include "scans/neighbour_graph.hpp"
#include "scans/point_origin.hpp"
#include "scans/point_skeleton.hpp"
#include "scans/shortest_path_tree.hpp"
#include "scans/tip_pruning.hpp"
#include "scans/voxel_thinning.hpp"

#include <algorithm>

namespace fspm::scans {

void EncodeOptions::validate() const {
  if (!(species.beta > 0.0) || !(species.gamma >= 0.0) || !(species.f_s > 0.0)) {
    throw ValueError("encoding: expected species beta > 0, gamma >= 0 and f_s > 0");
  }
  if (root_diameter_m && !(*root_diameter_m > 0.0)) {
    throw ValueError("encoding: root_diameter_m must be positive");
  }
  if (!(bin_length_m >= 0.0)) throw ValueError("encoding: bin_length_m must not be negative");
}

namespace {

// Side tips shorter than this many bins are spurs of the binning, not branches
// (scans/tip_pruning.hpp).
constexpr double kSpurBins = 4.0;

std::vector<ClusterHull> hulls(const ThinnedPoints& thin, const std::vector<PointCluster>& clusters,
                               const AlphaHullOptions& options) {
  const PointSet& ps = thin.points;
  std::vector<ClusterHull> out;
  std::vector<Eigen::Vector3d> pts;
  for (const PointCluster& c : clusters) {
    pts.clear();
    std::uint32_t count = 0;
    for (std::uint32_t i : c.points) pts.push_back(ps.points[i]), count += thin.counts[i];
    AlphaHull h = alpha_hull(pts, options);
    out.push_back(
        {c.seed_node, count, c.branch_length_m, std::move(h.vertices), std::move(h.triangles)});
  }
  return out;
}

// The voxel-thinned points, or every point with count 1 when thinning is off.
ThinnedPoints thinned(const PointSet& input, double voxel_m) {
  if (voxel_m < 0.0) return {input, std::vector<std::uint32_t>(input.points.size(), 1)};
  if (voxel_m == 0.0) {
    Eigen::Vector3d lo = input.points[0], hi = input.points[0];
    for (const Eigen::Vector3d& p : input.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    voxel_m = std::max((hi - lo).maxCoeff() / 1000.0, 1e-6);
  }
  return thin_to_voxels(input, voxel_m);
}

// The thinned points without the ground (scans/ground_filter.hpp), counts kept with them.
ThinnedPoints without_ground(ThinnedPoints thin, std::size_t& removed) {
  const std::vector<std::uint32_t> keep = above_ground(thin.points);
  removed = thin.points.points.size() - keep.size();
  if (keep.empty()) removed = 0;
  if (removed == 0) return thin;
  ThinnedPoints out;
  out.points.points.reserve(keep.size());
  out.counts.reserve(keep.size());
  for (std::uint32_t i : keep) {
    out.points.points.push_back(thin.points.points[i]);
    out.counts.push_back(thin.counts[i]);
  }
  return out;
}

}  // namespace

EncodeResult encode_point_set(const PointSet& absolute, const EncodeOptions& o) {
  o.validate();
  if (absolute.points.empty()) throw ValueError("the point set is empty");
  // The recentred copy and the voxel thinning (a point and a count per occupied voxel, a hash
  // entry while counting) hold up to three times the points at once.
  const auto n = static_cast<double>(absolute.points.size());
  check_memory(n * (3.0 * sizeof(Eigen::Vector3d) + 48.0),
               "encoding " + std::to_string(absolute.points.size()) +
                   " points (recentred copy and voxel thinning)");
  // Projected coordinates (x ~ 5e5 m, y ~ 6e6 m) are recentred: the results move back at the end.
  const Eigen::Vector3d origin = point_set_origin(absolute);
  const PointSet input = relative_to(absolute, origin);
  std::size_t ground = 0;
  const ThinnedPoints thin =
      o.keep_ground ? thinned(input, o.voxel_m) : without_ground(thinned(input, o.voxel_m), ground);
  const PointSet& ps = thin.points;
  // The neighbour graph (k edges of an index and a weight per point, both ways), its k-d tree,
  // and the shortest-path tree and skeleton bins (a few numbers per point).
  const auto m = static_cast<double>(ps.points.size());
  check_memory(n * sizeof(Eigen::Vector3d) +
                   m * (2.0 * o.neighbours * (sizeof(std::uint32_t) + sizeof(double)) + 96.0),
               "the neighbour graph of " + std::to_string(ps.points.size()) + " points (" +
                   std::to_string(o.neighbours) + " neighbours each)");
  const std::uint32_t root = trunk_base_point(ps);
  const NeighbourGraph graph = build_neighbour_graph(ps, o.neighbours, o.species.beta, root);
  const ShortestPathTree paths = shortest_path_tree(ps, graph, root);
  const double bin = o.bin_length_m > 0.0 ? o.bin_length_m : default_bin_length_m(paths);
  PointSkeleton skeleton = build_point_skeleton(ps, graph, paths, bin);
  set_branch_orders(skeleton.tree);
  double trunk_m = o.trunk_height_m;
  if (trunk_m <= 0.0) {
    double z0 = ps.points[root].z(), z1 = z0;
    for (const Eigen::Vector3d& p : ps.points) z1 = std::max(z1, p.z());
    trunk_m = std::min(1.3, 0.1 * (z1 - z0));
  }
  const double d_root =
      o.root_diameter_m ? *o.root_diameter_m : estimate_root_diameter_m(ps, skeleton, trunk_m);
  if (!(d_root > 0.0)) {
    throw ValueError(
        "no trunk diameter could be fitted (fewer than 5 trunk points, or no circle "
        "through them); give the root diameter (--root-diameter)");
  }
  set_allometric_radii(skeleton.tree, d_root, o.species.gamma);
  ClusterSplit split = split_clusters(ps, skeleton,
                                      {.f_s = o.species.f_s,
                                       .follow_main_axes = o.follow_main_axes,
                                       .main_branch_share = o.main_branch_share,
                                       .main_branch_reach = o.main_branch_reach,
                                       .spur_length_m = kSpurBins * bin});
  EncodeResult r;
  r.points = input.points.size();
  r.thinned_points = ps.points.size() + ground;
  r.ground_points = ground;
  r.bridges = graph.bridges;
  r.gap_m = graph.gap_m;
  for (const auto& [a, b] : graph.bridge_edges) {
    const double len = (ps.points[a] - ps.points[b]).norm();
    if (len > graph.gap_m) r.gaps.push_back({ps.points[a] + origin, ps.points[b] + origin, len});
  }
  r.model.species = o.species.name;
  r.model.beta = o.species.beta;
  r.model.gamma = o.species.gamma;
  r.model.f_s = o.species.f_s;
  r.model.root_diameter_m = d_root;
  r.model.clusters = hulls(thin, split.clusters, o.hull);
  r.model.skeleton = std::move(split.main_skeleton);
  r.branch_skeleton = without_short_tips(skeleton.tree, kSpurBins * bin);
  r.full_skeleton = std::move(skeleton.tree);
  r.origin = origin;
  translate_tree(r.model.skeleton, origin);
  translate_tree(r.full_skeleton, origin);
  translate_tree(r.branch_skeleton, origin);
  for (ClusterHull& h : r.model.clusters) {
    for (Eigen::Vector3d& v : h.vertices) v += origin;
  }
  return r;
}

}  // namespace fspm::scans
