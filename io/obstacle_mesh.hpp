#pragma once
// Triangle meshes of a scene's obstacles (environment::Scene, docs/formats.md) for
// pictures and mesh files: walls and boxes as six flat-shaded quads, spheres as UV spheres,
// triangle meshes as they are, of material obstacle (translucent obstacle when they let light
// through). The ground is left out (renders draw
// their own ground plane). In io/ (it needs environment), so graphics keeps depending on the core
// only.
#include <Eigen/Core>

#include "environment/occluders.hpp"
#include "environment/scene.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::io {

// Segments around a sphere's equator (half as many from pole to pole).
inline constexpr int kSphereSegments = 32;

// Six outward-facing quads (24 vertices, 12 triangles) on the surface of the box, following its
// rotation; the normals are the faces' (flat shading).
void append_box_mesh(const environment::Box& box, graphics::TriangleMesh& mesh);

// A UV sphere with `segments` (>= 3) meridians and segments / 2 (>= 2) parallels, radial normals.
void append_sphere_mesh(const Eigen::Vector3d& center, double radius_m, int segments,
                        graphics::TriangleMesh& mesh);

// The triangles as they are, with area-weighted vertex normals. Throws ValueError for an index
// out of range.
void append_triangle_mesh(const environment::TriangleMesh& surface, graphics::TriangleMesh& mesh);

// Every box, sphere (solid obstacles, spherical occluders and leaf clusters alike: the scene does
// not tell them apart) and triangle mesh of the scene, without attributes: of material kObstacle,
// or kTranslucentObstacle when its translucency is above 0.
graphics::TriangleMesh mesh_obstacles(const environment::Scene& scene,
                                      int sphere_segments = kSphereSegments);

}  // namespace fspm::io
