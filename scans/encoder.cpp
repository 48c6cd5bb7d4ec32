#include "scans/encoder.hpp"

#include "fspm/error.hpp"
#include "scans/allometry.hpp"
#include "scans/cluster_split.hpp"
#include "scans/neighbour_graph.hpp"
#include "scans/point_skeleton.hpp"
#include "scans/shortest_path_tree.hpp"

namespace fspm::scans {
namespace {

void check_options(const EncodeOptions& o) {
  const SpeciesParameters& s = o.species;
  if (!(s.beta > 0.0) || !(s.gamma >= 0.0) || !(s.f_s > 0.0)) {
    throw ValueError("expected beta > 0, gamma >= 0 and f_s > 0");
  }
  if (o.root_diameter_m && !(*o.root_diameter_m > 0.0)) {
    throw ValueError("the root diameter must be positive");
  }
  if (!(o.bin_length_m >= 0.0)) throw ValueError("the bin length must not be negative");
}

std::vector<ClusterHull> hulls(const PointSet& ps, const std::vector<PointCluster>& clusters,
                               const AlphaHullOptions& options) {
  std::vector<ClusterHull> out;
  std::vector<Eigen::Vector3d> pts;
  for (const PointCluster& c : clusters) {
    pts.clear();
    for (std::uint32_t i : c.points) pts.push_back(ps.points[i]);
    AlphaHull h = alpha_hull(pts, options);
    out.push_back({c.seed_node, static_cast<std::uint32_t>(c.points.size()), std::move(h.vertices),
                   std::move(h.triangles)});
  }
  return out;
}

}  // namespace

EncodeResult encode_point_set(const PointSet& ps, const EncodeOptions& o) {
  check_options(o);
  if (ps.points.empty()) throw ValueError("the point set is empty");
  const std::uint32_t root = lowest_point(ps);
  const NeighbourGraph graph = build_neighbour_graph(ps, o.neighbours, o.species.beta, root);
  const ShortestPathTree paths = shortest_path_tree(ps, graph, root);
  const double bin = o.bin_length_m > 0.0 ? o.bin_length_m : default_bin_length_m(paths);
  PointSkeleton skeleton = build_point_skeleton(ps, graph, paths, bin);
  set_branch_orders(skeleton.tree);
  const double d_root = o.root_diameter_m
                            ? *o.root_diameter_m
                            : estimate_root_diameter_m(ps, skeleton, o.trunk_height_m);
  if (!(d_root > 0.0)) {
    throw ValueError("no trunk diameter could be fitted to the points below " +
                     std::to_string(o.trunk_height_m) + " m; give the root diameter");
  }
  set_allometric_radii(skeleton.tree, d_root, o.species.gamma);
  ClusterSplit split = split_clusters(ps, skeleton, o.species.f_s);
  EncodeResult r;
  r.points = ps.points.size();
  r.bridges = graph.bridges;
  r.model.species = o.species.name;
  r.model.beta = o.species.beta;
  r.model.gamma = o.species.gamma;
  r.model.f_s = o.species.f_s;
  r.model.root_diameter_m = d_root;
  r.model.clusters = hulls(ps, split.clusters, o.hull);
  r.model.skeleton = std::move(split.main_skeleton);
  r.full_skeleton = std::move(skeleton.tree);
  return r;
}

}  // namespace fspm::scans
