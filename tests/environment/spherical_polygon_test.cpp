#include "environment/spherical_polygon.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "environment/sky.hpp"
#include "sky_quadrature.hpp"

namespace fspm::environment {
namespace {

using testing::sky_quadrature;

// The parallelogram center +- u +- v, as corners relative to the viewpoint (the origin).
std::array<Eigen::Vector3d, 4> parallelogram(const Eigen::Vector3d& center,
                                             const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return {center + u + v, center - u + v, center - u - v, center + u - v};
}

// True when the ray from the origin along d crosses the planar convex polygon (oracle, written
// here: ray-plane intersection, then the point on the inner side of every edge).
bool ray_meets_polygon(const Eigen::Vector3d& d, const std::array<Eigen::Vector3d, 4>& c) {
  const Eigen::Vector3d n = (c[1] - c[0]).cross(c[2] - c[0]);
  const double dn = d.dot(n);
  if (std::abs(dn) < 1e-300) return false;
  const double t = c[0].dot(n) / dn;
  if (t <= 0.0) return false;
  const Eigen::Vector3d x = t * d;
  for (int i = 0; i < 4; ++i) {
    if ((c[(i + 1) % 4] - c[i]).cross(x - c[i]).dot(n) < 0.0) return false;
  }
  return true;
}

struct Case {
  const char* name;
  std::array<Eigen::Vector3d, 4> corners;
};

std::vector<Case> cases() {
  using V = Eigen::Vector3d;
  return {
      {"around the zenith", parallelogram(V(0.3, -0.2, 2.0), V(1.0, 0.2, 0.1), V(-0.3, 1.5, 0.2))},
      {"off axis, tilted", parallelogram(V(2.0, 1.0, 1.5), V(0.4, 0.3, 0.6), V(-0.5, 0.8, 0.1))},
      {"crossing the horizon", parallelogram(V(3.0, 1.0, 0.5), V(0, 0, 2.0), V(-0.3, 1.0, 0))},
      {"wall face on the horizon", parallelogram(V(1, 0, 25), V(0, 30, 0), V(0, 0, 25))},
      {"zenith and horizon", parallelogram(V(0, 0, 1), V(8, 0, -4), V(0, 6, 0))},
      {"below the horizon", parallelogram(V(2, 0, -1), V(1, 0, 0), V(0, 1, 0.5))},
  };
}

// Closed forms (Arvo 1995) against a fine quadrature of (b.d)^2 and (b.d)^2 d over the directions
// whose rays cross the polygon, for a zenith and two tilted brightest points; both orientations.
TEST(SphericalPolygon, MomentsMatchQuadrature) {
  const std::array<Eigen::Vector3d, 3> brightest = {Eigen::Vector3d::UnitZ(),
                                                    direction_from_elevation_azimuth(35, 130),
                                                    direction_from_elevation_azimuth(10, 290)};
  for (const Case& c : cases()) {
    for (const Eigen::Vector3d& b : brightest) {
      const SphericalPolygon poly = project_to_upper_hemisphere(c.corners);
      const SphericalMoments m = polygon_moments(poly, b);
      const auto q = sky_quadrature(b, 800, 1600, [&](const Eigen::Vector3d& d) {
        return ray_meets_polygon(d, c.corners) ? 1.0 : 0.0;
      });
      const double tol = 2e-4 + 2e-3 * q.integral;
      EXPECT_NEAR(m.integral, q.integral, tol) << c.name << " b " << b.transpose();
      EXPECT_NEAR((m.moment - q.moment).norm(), 0.0, tol) << c.name << " b " << b.transpose();
      std::array<Eigen::Vector3d, 4> reversed = {c.corners[3], c.corners[2], c.corners[1],
                                                 c.corners[0]};
      const SphericalMoments r = polygon_moments(project_to_upper_hemisphere(reversed), b);
      EXPECT_NEAR(r.integral, m.integral, 1e-12) << c.name;
      EXPECT_NEAR((r.moment - m.moment).norm(), 0.0, 1e-12) << c.name;
    }
  }
}

// Exact values: a face seen edge-on or entirely below the horizon covers nothing; the upper half
// of an infinite-looking vertical plane x = 1 through the horizon approaches a quarter sphere.
TEST(SphericalPolygon, DegenerateAndLimitCases) {
  using V = Eigen::Vector3d;
  EXPECT_EQ(project_to_upper_hemisphere(parallelogram(V(2, 0, -2), V(1, 0, 0), V(0, 1, 0))).size,
            0);
  EXPECT_EQ(project_to_upper_hemisphere(parallelogram(V(2, 0, 0), V(1, 0, 0), V(0, 1, 0))).size,
            0);  // plane z = 0 through the viewpoint: edge-on
  const SphericalPolygon half =
      project_to_upper_hemisphere(parallelogram(V(1, 0, 0), V(0, 1e7, 0), V(0, 0, 1e7)));
  EXPECT_NEAR(half.solid_angle, std::numbers::pi, 1e-6);
  // Integral of z^2 over the quarter sphere x > 0, z > 0: pi / 3.
  EXPECT_NEAR(polygon_moments(half, V::UnitZ()).integral, std::numbers::pi / 3, 1e-6);
}

TEST(SphericalPolygon, BoxFacesTileTheSilhouette) {
  Box box;
  box.center = {1.5, -0.5, 2.0};
  box.half_extent = {0.6, 0.3, 0.9};
  box.rotation = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, 0.5, 1).normalized()).matrix();
  const Eigen::Vector3d p(0.2, 0.1, 0.4);
  const Eigen::Vector3d b = direction_from_elevation_azimuth(50, 40);
  std::array<SphericalPolygon, 3> faces;
  const int n = box_sky_polygons(box, p, faces);
  EXPECT_GE(n, 1);
  double integral = 0.0;
  for (int f = 0; f < n; ++f) integral += polygon_moments(faces[f], b).integral;
  const auto q = sky_quadrature(b, 800, 1600, [&](const Eigen::Vector3d& d) {
    return testing::ray_meets_box(p, d, box.center, box.half_extent, box.rotation) ? 1.0 : 0.0;
  });
  EXPECT_NEAR(integral, q.integral, 2e-4 + 2e-3 * q.integral);
}

TEST(SphericalPolygon, OverlapTests) {
  using V = Eigen::Vector3d;
  const SphericalPolygon a =
      project_to_upper_hemisphere(parallelogram(V(2, 0, 2), V(0.5, 0, 0), V(0, 0.5, 0)));
  const SphericalPolygon b =
      project_to_upper_hemisphere(parallelogram(V(-2, 0, 2), V(0.5, 0, 0), V(0, 0.5, 0)));
  const SphericalPolygon c =
      project_to_upper_hemisphere(parallelogram(V(2.4, 0, 2), V(0.5, 0, 0), V(0, 0.5, 0)));
  EXPECT_TRUE(polygons_disjoint(a, b));
  EXPECT_FALSE(polygons_disjoint(a, c));
  const V toward_a = V(2, 0, 2).normalized();
  EXPECT_TRUE(cap_meets_polygon(toward_a, std::cos(0.01), std::sin(0.01), a));  // inside
  const V up = V::UnitZ();
  EXPECT_FALSE(cap_meets_polygon(up, std::cos(0.3), std::sin(0.3), a));
  // Angular distance from the zenith to the polygon's nearest edge (x = 1.5): atan(1.5 / 2).
  const double gap = std::atan2(1.5, 2.0);
  EXPECT_TRUE(cap_meets_polygon(up, std::cos(gap + 0.01), std::sin(gap + 0.01), a));
  EXPECT_FALSE(cap_meets_polygon(up, std::cos(gap - 0.01), std::sin(gap - 0.01), a));
}

}  // namespace
}  // namespace fspm::environment
