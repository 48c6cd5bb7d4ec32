#include "io/scan_render_mesh.hpp"

#include <algorithm>
#include <cmath>

#include "environment/occluders.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/memory_budget.hpp"
#include "io/obstacle_mesh.hpp"
#include "scans/clusters_file.hpp"
#include "scans/point_origin.hpp"
#include "scans/point_set_file.hpp"

namespace fspm::io {
namespace {

// Gives the triangles from `first` on `material` (the obstacle helpers emit kObstacle).
void set_material(graphics::TriangleMesh& mesh, std::size_t first, graphics::Material material) {
  std::fill(mesh.materials.begin() + static_cast<std::ptrdiff_t>(first), mesh.materials.end(),
            material);
}

double largest_extent_m(const scans::PointSet& set) {
  if (set.points.empty()) return 0.0;
  Eigen::Vector3d lo = set.points.front(), hi = lo;
  for (const Eigen::Vector3d& p : set.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).maxCoeff();
}

// Meshes hold floats: at projected coordinates (x ~ 5e5 m, y ~ 6e6 m) a float keeps decimetres
// and the renderer's camera clips the scene away. A coordinate beyond kRenderGridM is drawn
// relative to the multiple of kRenderGridM below the set's minimum: the same for the files of one
// tree (a scan, its .clusters), so that --frame still matches them.
constexpr double kRenderGridM = 1000.0;

Eigen::Vector3d render_origin(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  if (points.empty()) return origin;
  Eigen::Vector3d lo = points.front();
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p);
  for (int c = 0; c < 3; ++c) {
    if (std::abs(lo[c]) > kRenderGridM) origin[c] = kRenderGridM * std::floor(lo[c] / kRenderGridM);
  }
  return origin;
}

}  // namespace

graphics::TriangleMesh mesh_point_set(const scans::PointSet& points, double radius_m,
                                      graphics::Material material) {
  // One sphere per point: the mesh, the renderer's copies of it (VTK's arrays, the OpenGL
  // buffers of the software renderer) and their working memory grow with the point count.
  // Measured peaks above an empty render: about 9 times the mesh's bytes for 7 000 points, 6
  // times for 29 000, 3.3 times for 2 and 5 million (7.7 and 18.7 GB), hence 4 times the mesh and
  // 64 MiB.
  graphics::TriangleMesh sphere;
  append_sphere_mesh(Eigen::Vector3d::Zero(), 1.0, kPointSphereSegments, sphere);
  const std::size_t n = points.points.size();
  constexpr double kRendererCopies = 4.0;
  constexpr double kRendererBytes = 64.0 * 1024 * 1024;
  check_memory(kRendererCopies * graphics::TriangleMesh::bytes_for(n * sphere.vertex_count(),
                                                                   n * sphere.triangle_count(), 0) +
                   kRendererBytes,
               "drawing " + std::to_string(n) +
                   " points as spheres (the mesh and the renderer's copies and buffers)");
  graphics::TriangleMesh mesh;
  for (const Eigen::Vector3d& p : points.points) {
    append_sphere_mesh(p, radius_m, kPointSphereSegments, mesh);
  }
  set_material(mesh, 0, material);
  return mesh;
}

graphics::TriangleMesh mesh_cluster_model(const scans::ClusterModel& model,
                                          const graphics::MeshOptions& options,
                                          double point_radius_m) {
  graphics::MeshOptions bark = options;
  bark.leaves = false;
  graphics::TriangleMesh mesh = graphics::mesh_tree(model.skeleton, bark);
  for (const scans::ClusterHull& hull : model.clusters) {
    const std::size_t first = mesh.triangles.size();
    if (hull.triangles.empty()) {
      mesh.append(mesh_point_set({hull.vertices}, point_radius_m, graphics::Material::kCrown));
      continue;
    }
    environment::TriangleMesh surface;
    surface.vertices = hull.vertices;
    for (const auto& t : hull.triangles) {
      surface.triangles.emplace_back(static_cast<int>(t[0]), static_cast<int>(t[1]),
                                     static_cast<int>(t[2]));
    }
    graphics::TriangleMesh part;
    append_triangle_mesh(surface, part);
    mesh.append(part);
    set_material(mesh, first, graphics::Material::kCrown);
  }
  return mesh;
}

Eigen::Vector3d recentre_for_render(TreeGraph& tree) {
  std::vector<Eigen::Vector3d> all;
  all.reserve(2 * tree.size());
  for (NodeId u = 0; u < tree.size(); ++u) all.push_back(tree.start(u)), all.push_back(tree.end(u));
  const Eigen::Vector3d origin = render_origin(all);
  if (!origin.isZero()) scans::translate_tree(tree, -origin);
  return origin;
}

std::optional<graphics::TriangleMesh> load_scan_render_mesh(const std::string& path,
                                                            const graphics::MeshOptions& options) {
  const FileKind kind = file_kind(path);
  if (kind == FileKind::kClusters) {
    scans::ClusterModel model = scans::read_clusters_file(path);
    scans::PointSet nodes;
    for (const auto& hull : model.clusters) {
      nodes.points.insert(nodes.points.end(), hull.vertices.begin(), hull.vertices.end());
    }
    std::vector<Eigen::Vector3d> all = nodes.points;
    for (NodeId u = 0; u < model.skeleton.size(); ++u) all.push_back(model.skeleton.end(u));
    const Eigen::Vector3d origin = render_origin(all);
    scans::translate_tree(model.skeleton, -origin);
    for (auto& hull : model.clusters) {
      for (Eigen::Vector3d& v : hull.vertices) v -= origin;
    }
    return mesh_cluster_model(model, options, kPointRadiusShare * largest_extent_m(nodes));
  }
  // Point sets; the grouped meshes (.obj, .gltf, .glb) are drawn as meshes, not as their vertices.
  if (is_point_set_kind(kind) && !is_grouped_mesh_kind(kind)) {
    scans::PointSet points = scans::read_point_set(path);
    const Eigen::Vector3d origin = render_origin(points.points);
    for (Eigen::Vector3d& p : points.points) p -= origin;
    return mesh_point_set(points, kPointRadiusShare * largest_extent_m(points));
  }
  return std::nullopt;
}

}  // namespace fspm::io
