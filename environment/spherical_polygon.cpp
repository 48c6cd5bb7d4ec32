#include "environment/spherical_polygon.hpp"

#include <cmath>

namespace fspm::environment {
namespace {

// Vertices closer than this (unit vectors) are merged; shorter edges carry no area.
constexpr double kMergeDistance = 1e-12;
// Polygons of smaller solid angle (sr) are empty: seen edge-on or rounding residue.
constexpr double kMinSolidAngle = 1e-14;
// Rounding margin of the overlap tests (sines and cosines of angles).
constexpr double kOverlapMargin = 1e-12;

// Signed solid angle of the spherical triangle (zenith, a, b) (Van Oosterom and Strackee 1983):
// tan(omega / 2) = z.(a x b) / (1 + z.a + a.b + b.z). With a and b in the upper hemisphere the
// triangle never reaches the antipode, so the atan2 branch is unambiguous.
double zenith_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return 2.0 * std::atan2(a.cross(b).z(), 1.0 + a.z() + a.dot(b) + b.z());
}

// Integrals along the arc from unit a over theta radians towards e (unit, e perpendicular to a):
// d(s) = cos(s) a + sin(s) e, and with alpha = w.a, beta = w.e
//   integral of (w.d) ds   = alpha sin(theta) + beta (1 - cos(theta)),
//   integral of (w.d)^2 ds = alpha^2 (theta/2 + sin(2 theta)/4) + beta^2 (theta/2 - sin(2 theta)/4)
//                            + alpha beta sin^2(theta).
struct ArcIntegrals {
  double first = 0.0;
  double second = 0.0;
};
ArcIntegrals arc_integrals(const Eigen::Vector3d& w, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& e, double theta) {
  const double alpha = w.dot(a), beta = w.dot(e);
  const double s = std::sin(theta), c = std::cos(theta), s2 = std::sin(2.0 * theta);
  return {alpha * s + beta * (1.0 - c), alpha * alpha * (0.5 * theta + 0.25 * s2) +
                                            beta * beta * (0.5 * theta - 0.25 * s2) +
                                            alpha * beta * s * s};
}

// Normalizes the vertices, drops repeated ones, orients them counterclockwise and fills the edge
// normals, arcs and solid angle.
void finish_polygon(SphericalPolygon& poly) {
  int kept = 0;
  for (int i = 0; i < poly.size; ++i) {
    const double norm = poly.vertex[i].norm();
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      poly.size = 0;
      return;
    }
    const Eigen::Vector3d v = poly.vertex[i] / norm;
    if (kept > 0 && (v - poly.vertex[kept - 1]).norm() < kMergeDistance) continue;
    poly.vertex[kept++] = v;
  }
  while (kept > 1 && (poly.vertex[kept - 1] - poly.vertex[0]).norm() < kMergeDistance) --kept;
  poly.size = kept >= 3 ? kept : 0;
  double omega = 0.0;
  for (int i = 0; i < poly.size; ++i) {
    omega += zenith_triangle(poly.vertex[i], poly.vertex[(i + 1) % poly.size]);
  }
  if (omega < 0.0) {
    for (int i = 0, j = poly.size - 1; i < j; ++i, --j) std::swap(poly.vertex[i], poly.vertex[j]);
    omega = -omega;
  }
  if (!(omega > kMinSolidAngle)) poly.size = 0;
  poly.solid_angle = poly.size > 0 ? omega : 0.0;
  for (int i = 0; i < poly.size; ++i) {
    const Eigen::Vector3d& a = poly.vertex[i];
    const Eigen::Vector3d& b = poly.vertex[(i + 1) % poly.size];
    const Eigen::Vector3d n = a.cross(b);
    const double sin_t = n.norm();
    poly.arc[i] = std::atan2(sin_t, a.dot(b));
    poly.normal[i] = sin_t > 0.0 ? Eigen::Vector3d(n / sin_t) : Eigen::Vector3d::Zero();
  }
}

}  // namespace

SphericalPolygon project_to_upper_hemisphere(std::span<const Eigen::Vector3d> corners) {
  // Sutherland-Hodgman against z >= 0: the plane z = 0 through the viewpoint projects onto the
  // horizon, so clipping the planar polygon clips its projection.
  SphericalPolygon poly;
  const int n = static_cast<int>(corners.size());
  if (n < 3 || n > 4) return poly;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& a = corners[i];
    const Eigen::Vector3d& b = corners[(i + 1) % n];
    if (a.z() >= 0.0) poly.vertex[poly.size++] = a;
    if ((a.z() >= 0.0) != (b.z() >= 0.0)) {
      Eigen::Vector3d x = a + (b - a) * (a.z() / (a.z() - b.z()));
      x.z() = 0.0;
      poly.vertex[poly.size++] = x;
    }
  }
  finish_polygon(poly);
  return poly;
}

int box_sky_polygons(const Box& box, const Eigen::Vector3d& p,
                     std::array<SphericalPolygon, 3>& out) {
  int count = 0;
  const Eigen::Vector3d rel = box.center - p;
  for (int axis = 0; axis < 3; ++axis) {
    const Eigen::Vector3d u = box.rotation.col(axis);
    const Eigen::Vector3d v = box.rotation.col((axis + 1) % 3) * box.half_extent[(axis + 1) % 3];
    const Eigen::Vector3d w = box.rotation.col((axis + 2) % 3) * box.half_extent[(axis + 2) % 3];
    for (const double side : {-1.0, 1.0}) {
      const Eigen::Vector3d face = rel + side * box.half_extent[axis] * u;
      // Turned towards p when p lies strictly outside the face's plane (edge-on faces cover no
      // solid angle).
      if (!(side * u.dot(face) < 0.0) || count == 3) continue;
      const std::array<Eigen::Vector3d, 4> corners = {face + v + w, face - v + w, face - v - w,
                                                      face + v - w};
      out[count] = project_to_upper_hemisphere(corners);
      if (out[count].size > 0) ++count;
    }
  }
  return count;
}

SphericalMoments polygon_moments(const SphericalPolygon& poly, const Eigen::Vector3d& b) {
  SphericalMoments out;
  if (poly.size == 0) return out;
  double tau1 = 0.0;                                    // tau^1(b), Lambert
  double boundary1 = 0.0;                               // sum_e (b.n_e) integral_e (b.d) ds
  Eigen::Vector3d boundary2 = Eigen::Vector3d::Zero();  // sum_e n_e integral_e (b.d)^2 ds
  for (int i = 0; i < poly.size; ++i) {
    const Eigen::Vector3d& n = poly.normal[i];
    const double theta = poly.arc[i];
    const ArcIntegrals e = arc_integrals(b, poly.vertex[i], n.cross(poly.vertex[i]), theta);
    const double bn = b.dot(n);
    tau1 += 0.5 * theta * bn;
    boundary1 += bn * e.first;
    boundary2 += e.second * n;
  }
  out.integral = (poly.solid_angle + boundary1) / 3.0;  // tau^2(b): recurrence with k = 1
  out.moment = 0.5 * tau1 * b + 0.25 * boundary2;
  return out;
}

SphericalPolygon intersect(const SphericalPolygon& a, const SphericalPolygon& b, bool& ok) {
  ok = true;
  SphericalPolygon cur = a, next;
  for (int e = 0; e < b.size && cur.size > 0; ++e) {
    // Keep the part of cur in the hemisphere n.d >= 0 of b's edge e; an arc from u to v with
    // su = n.u and sv = n.v of opposite signs crosses it at (su v - sv u) / (su - sv).
    const Eigen::Vector3d& n = b.normal[e];
    if (n.squaredNorm() == 0.0) continue;
    next.size = 0;
    for (int i = 0; i < cur.size; ++i) {
      const Eigen::Vector3d& u = cur.vertex[i];
      const Eigen::Vector3d& v = cur.vertex[(i + 1) % cur.size];
      const double su = n.dot(u), sv = n.dot(v);
      const int needed = (su >= 0.0 ? 1 : 0) + ((su >= 0.0) != (sv >= 0.0) ? 1 : 0);
      if (next.size + needed > SphericalPolygon::kMaxVertices) {
        ok = false;
        return SphericalPolygon{};
      }
      if (su >= 0.0) next.vertex[next.size++] = u;
      if ((su >= 0.0) != (sv >= 0.0)) next.vertex[next.size++] = (su * v - sv * u) / (su - sv);
    }
    finish_polygon(next);
    cur = next;
  }
  return cur;
}

bool cap_meets_polygon(const Eigen::Vector3d& c, double cos_a, double sin_a,
                       const SphericalPolygon& poly) {
  if (poly.size == 0) return false;
  bool inside = true;
  for (int i = 0; i < poly.size; ++i) {
    const Eigen::Vector3d& a = poly.vertex[i];
    const Eigen::Vector3d& b = poly.vertex[(i + 1) % poly.size];
    const Eigen::Vector3d& n = poly.normal[i];
    const double s = c.dot(n);  // sine of the distance to the edge's great circle
    if (s < 0.0) inside = false;
    if (c.dot(a) > cos_a - kOverlapMargin) return true;  // a vertex inside the cap
    if (std::abs(s) >= sin_a + kOverlapMargin) continue;
    // The point of the great circle nearest to c lies on the arc: the cap crosses the edge.
    const Eigen::Vector3d q = c - s * n;
    if (a.cross(q).dot(n) >= 0.0 && q.cross(b).dot(n) >= 0.0 && q.squaredNorm() > 0.0) return true;
  }
  return inside;
}

bool polygons_disjoint(const SphericalPolygon& a, const SphericalPolygon& b) {
  if (a.size == 0 || b.size == 0) return true;
  auto separates = [](const SphericalPolygon& edges, const SphericalPolygon& other) {
    for (int i = 0; i < edges.size; ++i) {
      bool all_out = true;
      for (int j = 0; j < other.size && all_out; ++j) {
        all_out = other.vertex[j].dot(edges.normal[i]) <= kOverlapMargin;
      }
      if (all_out && edges.normal[i].squaredNorm() > 0.0) return true;
    }
    return false;
  };
  return separates(a, b) || separates(b, a);
}

}  // namespace fspm::environment
