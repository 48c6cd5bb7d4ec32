#include "graphics/parallel_transport.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>

namespace fspm::graphics {
namespace {

TEST(ParallelTransport, RotationMatrixMatchesAxisAngle) {
  // Pirk eq. 6.5 against Eigen's independent Rodrigues implementation.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector3d n = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double theta = 3.0 * u(rng);
    const Eigen::Matrix3d expected = Eigen::AngleAxisd(theta, n).toRotationMatrix();
    EXPECT_TRUE(rotation_about_axis(n, theta).isApprox(expected, 1e-12));
  }
}

TEST(ParallelTransport, QuarterTurnInPlane) {
  // Tangent turns from +x to +y about +z: a normal along +z is untouched, one along +y goes to -x.
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY();
  EXPECT_TRUE(transport(Eigen::Vector3d::UnitZ(), x, y).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_TRUE(transport(y, x, y).isApprox(-x, 1e-12));
}

TEST(ParallelTransport, StraightRunKeepsNormal) {
  std::vector<Eigen::Vector3d> t(5, Eigen::Vector3d::UnitZ());
  const auto v = parallel_transport_normals(t, Eigen::Vector3d(1, 0, 0.5));
  for (const auto& vi : v) EXPECT_TRUE(vi.isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(ParallelTransport, NormalsStayUnitAndPerpendicularOnHelix) {
  // Helix tangents; the transported frame has zero twist, so after a full turn of a circle
  // (planar curve) the normal returns to itself.
  std::vector<Eigen::Vector3d> t;
  const int n = 360;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * M_PI * i / n;
    t.push_back(Eigen::Vector3d(-std::sin(a), std::cos(a), 0.0));
  }
  const auto v = parallel_transport_normals(t, Eigen::Vector3d(0, 0, 1));
  for (std::size_t i = 0; i < t.size(); ++i) {
    EXPECT_NEAR(v[i].norm(), 1.0, 1e-12);
    EXPECT_NEAR(v[i].dot(t[i]), 0.0, 1e-12);
  }
  EXPECT_TRUE(v.back().isApprox(v.front(), 1e-9));
  // A radial start normal rotates with the circle: at a quarter turn it points along -x... i.e.
  // it stays radial (planar curve: transport = rotation about the plane normal).
  const auto w = parallel_transport_normals(t, Eigen::Vector3d(1, 0, 0));
  EXPECT_TRUE(w[n / 4].isApprox(Eigen::Vector3d(0, 1, 0), 1e-9));
}

TEST(ParallelTransport, ReversedTangentFlipsFrame) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d v = transport(Eigen::Vector3d::UnitX(), z, -z);
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  EXPECT_NEAR(v.dot(z), 0.0, 1e-12);
}

}  // namespace
}  // namespace fspm::graphics
