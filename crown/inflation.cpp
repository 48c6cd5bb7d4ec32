#include "crown/inflation.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cstdlib>
#include <utility>

#include "crown/nested_dissection.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Numbers the inner pixels (the unknowns) and places silhouette pixels at (i, j, 0).
InflatedSheet number_pixels(const Mask& mask, Connectivity connectivity, int& unknowns) {
  InflatedSheet sheet;
  sheet.width = mask.width;
  sheet.height = mask.height;
  sheet.classes = classify_pixels(mask, connectivity);
  sheet.vertex.assign(sheet.classes.size(), -1);
  unknowns = 0;
  for (std::size_t p = 0; p < sheet.classes.size(); ++p) {
    if (sheet.classes[p] == PixelClass::kOutside) continue;
    sheet.vertex[p] = static_cast<int>(sheet.positions.size());
    const int x = static_cast<int>(p % mask.width);
    const int y = static_cast<int>(p / mask.width);
    sheet.positions.emplace_back(x, y, 0.0);
    unknowns += sheet.classes[p] == PixelClass::kInner;
  }
  return sheet;
}

// One row of eq. 4.2 per inner pixel: unknown neighbours into the matrix, fixed ones (silhouette,
// outer silhouette with the half-offset) into the right-hand side.
void assemble(const InflatedSheet& sheet, const std::vector<int>& unknown_of, double k,
              Triplets& triplets, Eigen::MatrixX3d& rhs) {
  for (std::size_t p = 0; p < sheet.classes.size(); ++p) {
    const int row = unknown_of[p];
    if (row < 0) continue;
    const int x = static_cast<int>(p % sheet.width);
    const int y = static_cast<int>(p / sheet.width);
    for (int dy = -2; dy <= 2; ++dy) {
      for (int dx = -2; dx <= 2; ++dx) {
        const double w = bilaplacian_weight(dx, dy);
        if (w == 0.0) continue;
        const int qx = x + dx;
        const int qy = y + dy;
        const bool in_raster = qx >= 0 && qy >= 0 && qx < sheet.width && qy < sheet.height;
        const std::size_t q = in_raster ? static_cast<std::size_t>(qy) * sheet.width + qx : 0;
        const PixelClass c = in_raster ? sheet.classes[q] : PixelClass::kOutside;
        if (c == PixelClass::kInner) {
          triplets.emplace_back(row, unknown_of[q], w);
        } else if (c == PixelClass::kSilhouette) {
          rhs.row(row) -= w * Eigen::RowVector3d(qx, qy, 0.0);
        } else {
          rhs.row(row) -= w * Eigen::RowVector3d(qx - 0.5 * dx, qy - 0.5 * dy, -k);
        }
      }
    }
  }
}

}  // namespace

double bilaplacian_weight(int dx, int dy) {
  const int manhattan = std::abs(dx) + std::abs(dy);
  if (manhattan == 0) return 20.0 / 16.0;
  if (manhattan == 1) return -8.0 / 16.0;
  if (manhattan == 2) return (dx == 0 || dy == 0) ? 1.0 / 16.0 : 2.0 / 16.0;
  return 0.0;
}

InflatedSheet inflate(const Mask& mask, const InflationOptions& options) {
  if (mask.count() == 0) throw ValueError("the crown mask has no crown pixel");
  if (!(options.k > 0.0)) throw ValueError("the outer silhouette depth k must be > 0");
  int unknowns = 0;
  InflatedSheet sheet = number_pixels(mask, options.connectivity, unknowns);
  if (unknowns == 0) return sheet;  // a crown only one or two pixels thick stays flat
  // The unknowns are numbered in nested dissection order, so the factorization needs no
  // fill-reducing permutation of its own: about 0.3 GFlop and 2.0 M factor entries for a disc of
  // 31 000 pixels against 0.7 GFlop and 2.6 M with Eigen's default approximate minimum degree.
  std::vector<std::size_t> inner;
  inner.reserve(static_cast<std::size_t>(unknowns));
  for (std::size_t p = 0; p < sheet.classes.size(); ++p) {
    if (sheet.classes[p] == PixelClass::kInner) inner.push_back(p);
  }
  const std::vector<std::size_t> pixel_of = nested_dissection_order(std::move(inner), mask.width);
  std::vector<int> unknown_of(sheet.classes.size(), -1);
  for (std::size_t u = 0; u < pixel_of.size(); ++u) unknown_of[pixel_of[u]] = static_cast<int>(u);
  Triplets triplets;
  triplets.reserve(static_cast<std::size_t>(unknowns) * 13);
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(unknowns, 3);
  assemble(sheet, unknown_of, options.k, triplets, rhs);
  Eigen::SparseMatrix<double> a(unknowns, unknowns);
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>>
      solver(a);
  if (solver.info() != Eigen::Success)
    throw ValueError("the inflation system could not be factored");
  const Eigen::MatrixX3d solution = solver.solve(rhs);
  for (int u = 0; u < unknowns; ++u) {
    sheet.positions[static_cast<std::size_t>(sheet.vertex[pixel_of[static_cast<std::size_t>(u)]])] =
        solution.row(u).transpose();
  }
  return sheet;
}

}  // namespace fspm::crown
