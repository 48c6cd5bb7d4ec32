#pragma once
// The cos^2 sky of Pirk eq. 4.3 integrated in closed form over spherical polygons: a box seen
// from a point covers the union of the spherical projections of the faces turned towards it
// (convex quadrilaterals, at most three, disjoint), each clipped to the upper hemisphere.
//
// The integrals are Arvo's (1995) axial and double-axis moments of a polygon A with great-arc
// edges, reduced to sums over the edges by Stokes' theorem on the sphere. With the vertices
// counterclockwise seen from outside the sphere, n_e the unit normal of edge e's plane
// (v_e x v_e+1, pointing into A), Theta_e its arc length and tau^k(w) = integral over A of
// (w.d)^k dw:
//   tau^0     = the solid angle of A,
//   tau^1(w)  = 1/2 sum_e Theta_e (w.n_e)                           (Lambert's formula),
//   tau^k+1(w) = [k tau^k-1(w) + sum_e (w.n_e) integral_e (w.d)^k ds] / (k + 2),
//   integral over A of (b.d)^2 d = 1/2 tau^1(b) b + 1/4 sum_e n_e integral_e (b.d)^2 ds.
// The recurrence is Arvo's axial-moment recurrence (surface divergence of (w.d)^k (w - (w.d) d));
// the last line is the double-axis moment of order (2, 1) (divergence of (b.d)^2 (v - (v.d) d)).
// Reference: J. Arvo, "Applications of irradiance tensors to the simulation of non-Lambertian
// phenomena", SIGGRAPH 95, pp. 335-342.
#include <Eigen/Core>
#include <array>
#include <span>

#include "environment/occluders.hpp"

namespace fspm::environment {

// A convex spherical polygon in the closed upper hemisphere: unit vertices counterclockwise seen
// from outside the sphere, with the inward unit normal of each edge (vertex i to i + 1).
struct SphericalPolygon {
  // A clipped face has at most 5 vertices, the intersection of convex m- and n-gons m + n.
  static constexpr int kMaxVertices = 16;
  std::array<Eigen::Vector3d, kMaxVertices> vertex;
  std::array<Eigen::Vector3d, kMaxVertices> normal;
  std::array<double, kMaxVertices> arc{};  // edge lengths Theta_e (radians)
  int size = 0;                            // 0: empty
  double solid_angle = 0.0;
};

struct SphericalMoments {
  double integral = 0.0;                             // integral of (b.d)^2 over the polygon
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // integral of (b.d)^2 d
};

// Builds the polygon seen from the origin through the planar polygon `corners` (positions relative
// to the viewpoint, either orientation, at most 4), clipped to z >= 0. Empty when nothing of it
// lies above the horizon or it degenerates (seen edge-on, a corner at the viewpoint).
SphericalPolygon project_to_upper_hemisphere(std::span<const Eigen::Vector3d> corners);

// The projections of the faces of `box` turned towards p (clipped to p's upper hemisphere); they
// do not overlap and together cover the directions in which rays from p enter the box. Returns how
// many were written (0 to 3). p must lie outside the box.
int box_sky_polygons(const Box& box, const Eigen::Vector3d& p,
                     std::array<SphericalPolygon, 3>& out);

// Closed-form moments of the sky weight (b.d)^2 over the polygon (b unit), see the header comment.
SphericalMoments polygon_moments(const SphericalPolygon& polygon, const Eigen::Vector3d& b);

// The intersection of two polygons (convex, so one clipped by the other's edge hemispheres).
// `ok` is false when it would exceed kMaxVertices (the result is then empty and unusable).
SphericalPolygon intersect(const SphericalPolygon& a, const SphericalPolygon& b, bool& ok);

// True when the cap of unit axis c and half angle alpha (< 90 degrees) shares interior with the
// polygon; conservative (true) within a rounding margin.
bool cap_meets_polygon(const Eigen::Vector3d& c, double cos_a, double sin_a,
                       const SphericalPolygon& polygon);

// True when the interiors of two polygons are separated by one of their edges' great circles (a
// sufficient test: polygons touching the horizon may be reported as overlapping).
bool polygons_disjoint(const SphericalPolygon& a, const SphericalPolygon& b);

}  // namespace fspm::environment
