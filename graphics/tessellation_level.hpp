#pragma once
// Level of detail per face after Reynolds et al. 2011, section 3.3, expression 2: the
// tessellation level grows linearly as the viewer approaches and with the face's area,
//   level = (1 - d / D_max) (A / A_max) L_max,
// d the face's distance from the viewer, D_max the distance at which tessellation begins, A the
// face's area, A_max the largest face area, L_max the highest level. A level of 0 removes the face
// (Reynolds' face culling): faces at or beyond D_max are culled. The two factors are clamped to
// [0, 1], so a viewer inside D_max never gets a negative level and no face exceeds L_max.
#include <Eigen/Core>
#include <vector>

#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct TessellationLimits {
  double max_distance_m = 50.0;   // D_max
  double max_face_area_m2 = 1.0;  // A_max
  double max_level = 16.0;        // L_max

  // Throws ValueError unless every limit is positive and finite.
  void validate() const;
};

// Expression 2 (clamped factors). Throws ValueError for a negative distance or area.
double tessellation_level(double face_distance_m, double face_area_m2,
                          const TessellationLimits& limits);

// Expression 2 for every triangle of `mesh` seen from `viewer_m`: the distance to the triangle's
// centroid and its area; A_max the largest triangle area of the mesh when limits.max_face_area_m2
// is 0 (Reynolds computes areas once, as a preprocessing step).
std::vector<double> face_tessellation_levels(const TriangleMesh& mesh,
                                             const Eigen::Vector3f& viewer_m,
                                             TessellationLimits limits);

// Reynolds' face culling by branch level (3.3): "at key distances the highest visible level of
// branches will be completely removed", the leaves hiding the change. `mesh` without the bark
// triangles of its `dropped` highest branching orders (the vertex attribute "order" of the
// mesher, absolute in flattened compressed plants); the trunk (order 0), the leaves and every
// other material are kept, the vertices left as they are. A mesh without the attribute comes
// back unchanged. Throws ValueError for dropped < 0.
TriangleMesh without_highest_bark_orders(const TriangleMesh& mesh, int dropped);

}  // namespace fspm::graphics
