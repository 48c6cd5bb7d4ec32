#pragma once
// Meshes that let fspm render draw the stages of encoding a scan (Pirk 2013, sec. 3.3): a point
// set as small spheres, and a cluster-based tree (.clusters) as its skeleton's tubes with each
// cluster's alpha-shape hull as a translucent volume. In io/ (it needs scans and graphics), so
// graphics keeps depending on the core only.
#include <optional>
#include <string>

#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "scans/cluster_model.hpp"
#include "scans/point_set.hpp"

namespace fspm::io {

// Meridians of the sphere drawn at each point: a coarse sphere, since a scan has 10^4-10^5 points.
inline constexpr int kPointSphereSegments = 6;

// The radius of the sphere drawn at each point: this share of the set's largest extent, so that
// the points of a tree a few metres high are a few pixels wide in a figure.
inline constexpr double kPointRadiusShare = 0.002;

// One bark sphere of `radius_m` around each point.
graphics::TriangleMesh mesh_point_set(const scans::PointSet& points, double radius_m,
                                      graphics::Material material = graphics::Material::kBark);

// The skeleton meshed as a tree (its eq. 3.1 radii, no leaves) and every cluster hull in the
// translucent crown material; a cluster spanning no volume (points, no triangles) as small
// spheres of `point_radius_m` in that material.
graphics::TriangleMesh mesh_cluster_model(const scans::ClusterModel& model,
                                          const graphics::MeshOptions& options,
                                          double point_radius_m);

// For `fspm render`: the mesh of a point set (.ply, .xyz, .txt, .csv, .pcd, .las) or of a
// .clusters file, nullopt for any other extension. Coordinates beyond 1 km are drawn relative to
// the kilometre below the data's minimum (floats keep decimetres at projected coordinates). Throws
// the readers' errors.
std::optional<graphics::TriangleMesh> load_scan_render_mesh(const std::string& path,
                                                            const graphics::MeshOptions& options);

// A tree (a skeleton from fspm encode) moved by the same rule as the point sets above, so that it
// is framed wherever it lies and matches the scan it came from under --frame. Returns the offset
// subtracted (zero within 1 km of the origin).
Eigen::Vector3d recentre_for_render(TreeGraph& tree);

}  // namespace fspm::io
