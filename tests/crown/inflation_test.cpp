// Inflation (Argudo 4.3.2) against closed forms: a disc becomes a sphere, an ellipse an
// ellipsoid-like crown; a 4-connected silhouette does not give the sphere (Argudo Fig. 4.13).
#include "crown/inflation.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "crown/base_mesh.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

constexpr double kCentre = 127.5;  // of a 256 x 256 raster

Mask ellipse_mask(double a, double b) {
  Mask m(256, 256);
  for (int y = 0; y < 256; ++y) {
    for (int x = 0; x < 256; ++x) {
      const double u = (x - kCentre) / a, v = (y - kCentre) / b;
      m.set(x, y, u * u + v * v <= 1.0);
    }
  }
  return m;
}

// Front sheet depth scaled so its deepest point is `depth` pixels (the module's depth ratio).
std::vector<Eigen::Vector3d> scaled(const InflatedSheet& s, double depth) {
  double zmax = 0.0;
  for (const auto& p : s.positions) zmax = std::max(zmax, p.z());
  std::vector<Eigen::Vector3d> out = s.positions;
  for (auto& p : out) p.z() *= depth / zmax;
  return out;
}

// Mean and largest |(x/a)^2 + (y/b)^2 + (z/c)^2 - 1|-style error as a relative radius error:
// the distance to the centre in the coordinates that make the ellipsoid a unit sphere.
std::pair<double, double> ellipsoid_error(const std::vector<Eigen::Vector3d>& ps, double a,
                                          double b, double c) {
  double sum = 0.0, worst = 0.0;
  for (const auto& p : ps) {
    const double u = (p.x() - kCentre) / a, v = (p.y() - kCentre) / b, w = p.z() / c;
    const double e = std::abs(std::sqrt(u * u + v * v + w * w) - 1.0);
    sum += e;
    worst = std::max(worst, e);
  }
  return {sum / static_cast<double>(ps.size()), worst};
}

TEST(Inflation, StencilIsTheSquaredFivePointLaplacian) {
  // (L * L)(d) for L = [0 1 0; 1 -4 1; 0 1 0], brute force, divided by 16 as in eq. 4.2.
  const int l[3][3] = {{0, 1, 0}, {1, -4, 1}, {0, 1, 0}};
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      int sum = 0;
      for (int ay = -1; ay <= 1; ++ay) {
        for (int ax = -1; ax <= 1; ++ax) {
          const int by = dy - ay, bx = dx - ax;
          if (std::abs(by) <= 1 && std::abs(bx) <= 1) sum += l[ay + 1][ax + 1] * l[by + 1][bx + 1];
        }
      }
      EXPECT_DOUBLE_EQ(bilaplacian_weight(dx, dy), sum / 16.0) << dx << "," << dy;
    }
  }
}

// The disc of radius 100 (pixel centres within 100 of its centre) spans 200 pixels edge to edge;
// its silhouette pixel centres lie 99.5 from the centre on average and are moved to the border.
TEST(Inflation, DiscBecomesSphere) {
  const double r = 100.0;
  const InflatedSheet s = inflate(ellipse_mask(100.0, 100.0), {2.0, Connectivity::kEight});
  const auto [mean, worst] = ellipsoid_error(scaled(s, r), r, r, r);
  std::cout << "disc: mean radius error " << mean << ", worst " << worst << "\n";
  EXPECT_LT(mean, 0.01);    // radius error of the crown surface, on average
  EXPECT_LT(worst, 0.025);  // and at the worst vertex, near the rim
  // Unscaled, k = 2 already gives nearly the sphere's depth (Argudo Fig. 4.13, right).
  double zmax = 0.0;
  for (const auto& p : s.positions) zmax = std::max(zmax, p.z());
  EXPECT_NEAR(zmax, r, 0.05 * r);
}

// The border of the disc of radius 100 is the circle of radius 100 (the disc's pixels cover
// pi 100^2 to 1e-4): silhouette vertices are placed on it, not at their centres 99.5 away.
TEST(Inflation, SilhouetteLiesOnTheBorder) {
  const Mask mask = ellipse_mask(100.0, 100.0);
  const InflatedSheet s = inflate(mask, {2.0, Connectivity::kEight});
  double sum = 0.0, centres = 0.0, worst = 0.0, n = 0.0;
  for (std::size_t p = 0; p < s.classes.size(); ++p) {
    if (s.classes[p] != PixelClass::kSilhouette) continue;
    const Eigen::Vector3d& q = s.positions[static_cast<std::size_t>(s.vertex[p])];
    const double d = std::hypot(q.x() - kCentre, q.y() - kCentre);
    sum += d, n += 1.0, worst = std::max(worst, std::abs(d - 100.0));
    centres +=
        std::hypot(static_cast<double>(p % 256) - kCentre, static_cast<double>(p / 256) - kCentre);
    EXPECT_EQ(q.z(), 0.0);
  }
  std::cout << "silhouette: mean distance " << sum / n << " (centres " << centres / n << "), worst "
            << worst << "\n";
  EXPECT_NEAR(sum / n, 100.0, 0.1);
  EXPECT_LT(worst, 0.6);
  EXPECT_LT(centres / n, 99.8);  // the centres themselves lie inside
}

TEST(Inflation, EllipseBecomesEllipsoidLikeCrown) {
  const double a = 110.0, b = 70.0;  // wide crown: depth scaled to its half width
  const InflatedSheet s = inflate(ellipse_mask(a, b), {2.0, Connectivity::kEight});
  const auto [mean, worst] = ellipsoid_error(scaled(s, a), a, b, a);
  std::cout << "ellipse: mean ellipsoid radius error " << mean << ", worst " << worst << "\n";
  EXPECT_LT(mean, 0.03);
  EXPECT_LT(worst, 0.08);
}

TEST(Inflation, FourConnectedSilhouetteIsNoSphere) {
  const double r = 100.0;
  const InflatedSheet s8 = inflate(ellipse_mask(r, r), {2.0, Connectivity::kEight});
  const InflatedSheet s4 = inflate(ellipse_mask(r, r), {2.0, Connectivity::kFour});
  const auto e8 = ellipsoid_error(scaled(s8, r), r, r, r);
  const auto e4 = ellipsoid_error(scaled(s4, r), r, r, r);
  std::cout << "4-connected: mean radius error " << e4.first << ", worst " << e4.second
            << "; 8-connected: " << e8.first << ", " << e8.second << "\n";
  EXPECT_GT(e4.first, 2.0 * e8.first);
  // The thicker silhouette leaves fewer unknowns: every diagonal step of the rim is one more pixel.
  EXPECT_LT(std::count(s4.classes.begin(), s4.classes.end(), PixelClass::kInner),
            std::count(s8.classes.begin(), s8.classes.end(), PixelClass::kInner));
}

TEST(Inflation, MirroredMeshEnclosesTheSphereVolume) {
  const double r = 100.0;
  const InflatedSheet s = inflate(ellipse_mask(100.0, 100.0), {2.0, Connectivity::kEight});
  BaseMesh base = mirrored_mesh(s);
  double zmax = 0.0;
  for (const auto& p : base.mesh.positions) zmax = std::max(zmax, static_cast<double>(p.z()));
  for (auto& p : base.mesh.positions) p.z() *= static_cast<float>(r / zmax);
  const double volume = enclosed_volume(base.mesh, 0, base.mesh.crown_triangles);
  const double sphere = 4.0 / 3.0 * M_PI * r * r * r;
  std::cout << "sphere volume: " << volume / sphere << " of 4/3 pi r^3\n";
  EXPECT_NEAR(volume, sphere, 0.04 * sphere);  // closed and outward: positive, near 4/3 pi r^3
}

// The solve in nested dissection order against the same system solved the plain way: unknowns in
// raster order, Eigen's SimplicialLDLT with its default minimum degree ordering, assembled here
// from eq. 4.2 with the boundary conditions spelled out again. A non-convex crown (two discs and a
// notch) so that the dissection meets several pieces.
TEST(Inflation, NestedDissectionSolveMatchesRasterOrderSolve) {
  const int w = 48, h = 40;
  Mask mask(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool left = (x - 15) * (x - 15) + (y - 20) * (y - 20) <= 14 * 14;
      const bool right = (x - 32) * (x - 32) + (y - 18) * (y - 18) <= 13 * 13;
      const bool notch = y > 24 && x > 21 && x < 27;
      mask.set(x, y, (left || right) && !notch);
    }
  }
  const double k = 2.0;
  const InflatedSheet sheet = inflate(mask, {k, Connectivity::kEight});
  const auto classes = classify_pixels(mask, Connectivity::kEight);
  std::vector<int> row_of(classes.size(), -1);
  int n = 0;
  for (std::size_t p = 0; p < classes.size(); ++p) {
    if (classes[p] == PixelClass::kInner) row_of[p] = n++;
  }
  ASSERT_GT(n, 500);
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
  for (std::size_t p = 0; p < classes.size(); ++p) {
    if (row_of[p] < 0) continue;
    const int x = static_cast<int>(p) % w, y = static_cast<int>(p) / w;
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        const double m = bilaplacian_weight(dx, dy);
        const int qx = x + dx, qy = y + dy;
        const PixelClass c = classes[static_cast<std::size_t>(qy * w + qx)];  // mask has a margin
        if (m == 0.0) continue;
        if (c == PixelClass::kInner) {
          triplets.emplace_back(row_of[p], row_of[static_cast<std::size_t>(qy * w + qx)], m);
        } else if (c == PixelClass::kSilhouette) {
          // Fixed where inflate placed it (on the border, checked in SilhouetteLiesOnTheBorder).
          const auto& fixed = sheet.positions[static_cast<std::size_t>(sheet.vertex[qy * w + qx])];
          rhs.row(row_of[p]) -= m * fixed.transpose();
        } else {
          // Moved with the border as the silhouette pixels between p and q: p + d/2 for a
          // straight step of two, p's two 4-neighbours toward a diagonal one.
          Eigen::Vector2d shift = Eigen::Vector2d::Zero();
          int ns = 0;
          const std::vector<std::pair<int, int>> between =
              dx == 0 || dy == 0 ? std::vector<std::pair<int, int>>{{x + dx / 2, y + dy / 2}}
                                 : std::vector<std::pair<int, int>>{{x + dx, y}, {x, y + dy}};
          for (const auto& [sx, sy] : between) {
            const auto s = static_cast<std::size_t>(sy * w + sx);
            if (classes[s] != PixelClass::kSilhouette) continue;
            shift += sheet.positions[static_cast<std::size_t>(sheet.vertex[s])].head<2>() -
                     Eigen::Vector2d(sx, sy);
            ++ns;
          }
          if (ns > 0) shift /= ns;
          rhs.row(row_of[p]) -=
              m * Eigen::RowVector3d(qx - 0.5 * dx + shift.x(), qy - 0.5 * dy + shift.y(), -k);
        }
      }
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(triplets.begin(), triplets.end());
  const Eigen::MatrixX3d expected =
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(a).solve(rhs);
  Eigen::MatrixX3d got(n, 3);
  for (std::size_t p = 0; p < classes.size(); ++p) {
    if (row_of[p] >= 0) {
      got.row(row_of[p]) = sheet.positions[static_cast<std::size_t>(sheet.vertex[p])].transpose();
    }
  }
  EXPECT_LT((got - expected).norm(), 1e-9 * expected.norm());
  EXPECT_LT((got.col(2) - expected.col(2)).norm(), 1e-9 * expected.col(2).norm());
  EXPECT_GT(expected.col(2).minCoeff(), 0.0);  // a real inflation, not an all-zero solve
}

TEST(Inflation, RejectsEmptyMaskAndBadDepth) {
  EXPECT_THROW(inflate(Mask(8, 8), {}), Error);
  EXPECT_THROW(inflate(ellipse_mask(20, 20), {0.0, Connectivity::kEight}), Error);
}

}  // namespace
}  // namespace fspm::crown
