#pragma once
// Curved point-normal triangles (Vlachos, Peters, Boyd and Mitchell 2001): each triangle of a
// coarse mesh becomes a cubic Bezier triangle through its three corners and tangent to their
// normals, with a quadratic normal field, so a branch meshed with few sides is drawn round when
// it is tessellated. The surface along an edge depends on that edge's two corners only, so
// neighbouring triangles meet on the same curve. This is how the viewer places the vertices the
// tessellation shaders add (Reynolds et al. 2011, 3.3, tessellate a coarse continuous branch mesh
// by expression 2; they position new vertices by the skeleton, we by the surface's normals), and
// the CPU path where a context has no tessellation shaders.
#include <Eigen/Core>
#include <array>

#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct PnTriangle {
  // Control points b_ijk (i for the first corner, j the second, k the third): b300, b030, b003,
  // b210, b120, b021, b012, b102, b201, b111.
  std::array<Eigen::Vector3f, 10> b;
  // Normal coefficients: n200, n020, n002, n110, n011, n101.
  std::array<Eigen::Vector3f, 6> n;
};

// Vlachos et al. 2001, section 3: the edge control points are the corners moved a third of
// the way along the edge and projected onto the corner's tangent plane; the centre one is the
// mean of the six plus half its distance from the corners' centroid. Normals: unit length.
PnTriangle pn_triangle(const std::array<Eigen::Vector3f, 3>& corners,
                       const std::array<Eigen::Vector3f, 3>& normals);

// The surface and its (unit) normal at barycentric coordinates (w1, w2, w3), w1 + w2 + w3 = 1.
Eigen::Vector3f pn_point(const PnTriangle& t, const Eigen::Vector3f& w);
Eigen::Vector3f pn_normal(const PnTriangle& t, const Eigen::Vector3f& w);

// Every triangle of `mesh` split into level^2 triangles on its PN surface (uniform barycentric
// grid), vertex attributes, texture coordinates and materials carried over linearly; level 1
// returns a copy. The CPU path of the viewer's tessellation: one level for the whole mesh, so no
// cracks open between triangles of different levels. Throws ValueError for level < 1.
TriangleMesh tessellate_pn(const TriangleMesh& mesh, int level);

}  // namespace fspm::graphics
