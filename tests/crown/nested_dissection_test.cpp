// Nested dissection order of pixel sets: a permutation of the pixels, and an elimination order
// whose Cholesky factor of the 13-point system (eq. 4.2) has fewer entries than the raster order's
// (its row envelopes, counted by hand below) and than Eigen's minimum degree ordering.
#include "crown/nested_dissection.hpp"

#include <gtest/gtest.h>

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <iostream>

#include "crown/inflation.hpp"

namespace fspm::crown {
namespace {

// Entries of the factor L (diagonal included) of the 13-point system on an n x n grid of
// unknowns numbered by `order` (row-major pixel indices), from Eigen's symbolic analysis.
template <typename Ordering>
long factor_entries(int n, const std::vector<std::size_t>& order) {
  std::vector<int> unknown(static_cast<std::size_t>(n * n), -1);
  for (std::size_t u = 0; u < order.size(); ++u) unknown[order[u]] = static_cast<int>(u);
  std::vector<Eigen::Triplet<double>> t;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      for (int dy = -2; dy <= 2; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= n || qy >= n || bilaplacian_weight(dx, dy) == 0.0) continue;
          t.emplace_back(unknown[static_cast<std::size_t>(y * n + x)],
                         unknown[static_cast<std::size_t>(qy * n + qx)],
                         bilaplacian_weight(dx, dy));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> a(n * n, n * n);
  a.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Ordering> ldlt;
  ldlt.analyzePattern(a);
  ldlt.factorize(a);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return ldlt.matrixL().nestedExpression().nonZeros() + n * n;
}

TEST(NestedDissection, IsAPermutation) {
  std::vector<std::size_t> pixels;
  for (std::size_t p = 0; p < 5000; p += 3) pixels.push_back(p);  // scattered in a 100-wide raster
  std::vector<std::size_t> order = nested_dissection_order(pixels, 100);
  EXPECT_NE(order, pixels);
  std::sort(order.begin(), order.end());
  EXPECT_EQ(order, pixels);
}

TEST(NestedDissection, FillsLessThanRasterOrderAndMinimumDegree) {
  const int n = 60;
  std::vector<std::size_t> raster(static_cast<std::size_t>(n * n));
  for (std::size_t p = 0; p < raster.size(); ++p) raster[p] = p;
  // Raster order: the factor fills each row's envelope, from the row's first stencil neighbour
  // (two rows up, or less on the first two rows) to the diagonal.
  long band = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      int first = y * n + x;
      for (int dy = -2; dy <= 0; ++dy) {
        for (int dx = -2; dx <= 2; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx >= 0 && qy >= 0 && qx < n && bilaplacian_weight(dx, dy) != 0.0)
            first = std::min(first, qy * n + qx);
        }
      }
      band += y * n + x - first + 1;
    }
  }
  EXPECT_EQ(factor_entries<Eigen::NaturalOrdering<int>>(n, raster), band);
  const long nested =
      factor_entries<Eigen::NaturalOrdering<int>>(n, nested_dissection_order(raster, n));
  const long amd = factor_entries<Eigen::AMDOrdering<int>>(n, raster);
  std::cout << "factor entries: raster " << band << ", minimum degree " << amd
            << ", nested dissection " << nested << "\n";
  EXPECT_LT(nested, band / 2);
  EXPECT_LT(nested, amd);
}

}  // namespace
}  // namespace fspm::crown
