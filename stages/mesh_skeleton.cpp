#include "stages/mesh_skeleton.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/error.hpp"
#include "stages/skeleton_graph.hpp"
#include "stages/skeleton_tree.hpp"
#include "stages/spur_pruning.hpp"
#include "stages/vertex_joining.hpp"

namespace fspm::stages {
namespace {

double median_displacement(const BranchMesh& mesh, const Eigen::MatrixX3d& contracted) {
  std::vector<double> d(mesh.vertices.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    d[i] = (mesh.vertices[i] - contracted.row(static_cast<Eigen::Index>(i)).transpose()).norm();
  }
  const auto mid = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), mid, d.end());
  return *mid;
}

double bbox_diagonal(const std::vector<Eigen::Vector3d>& v) {
  Eigen::Vector3d lo = v.front(), hi = v.front();
  for (const Eigen::Vector3d& p : v) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace

void MeshSkeletonParams::validate() const {
  contraction.validate();
  if (!(join_distance_m >= 0.0) || !std::isfinite(join_distance_m)) {
    throw ValueError("the joining distance must be 0 (automatic) or positive, got " +
                     std::to_string(join_distance_m));
  }
  if (!(join_factor > 0.0) || !(link_factor > 0.0) || !(spur_factor >= 0.0)) {
    throw ValueError(
        "the joining and linking factors must be positive, the spur factor not "
        "negative");
  }
}

MeshSkeleton mesh_skeleton(const BranchMesh& mesh, const MeshSkeletonParams& params) {
  params.validate();
  MeshSkeleton out;
  const Contraction c = contract_mesh(mesh, params.contraction);
  out.iterations = c.iterations;
  out.area_ratio = c.area_ratio;
  double t_dist = params.join_distance_m > 0.0
                      ? params.join_distance_m
                      : params.join_factor * median_displacement(mesh, c.positions);
  // Not finer than a millionth of the mesh's extent: the joining grid's cells stay countable.
  t_dist = std::max(t_dist, 1e-6 * bbox_diagonal(mesh.vertices));
  out.join_distance_m = t_dist;
  const JoinedVertices joined = join_vertices(c.positions, t_dist);
  out.joined_vertices = joined.positions.size();
  const std::vector<SkeletonEdge> edges =
      prune_spurs(skeleton_spanning_tree(joined, mesh.triangles, params.link_factor * t_dist),
                  joined.positions, params.spur_factor * t_dist);
  out.tree = skeleton_tree(joined, edges, mesh.vertices);
  return out;
}

}  // namespace fspm::stages
