#include "stages/mesh_laplacian.hpp"

#include <algorithm>
#include <cmath>

namespace fspm::stages {
namespace {

// cot of the angle at `o` between the edges to `a` and `b`.
double cotangent(const Eigen::Vector3d& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d u = a - o, v = b - o;
  const double sine = u.cross(v).norm();
  const double cosine = u.dot(v);
  if (sine <= 1e-300) return cosine >= 0.0 ? kMaxCotangent : -kMaxCotangent;
  return std::clamp(cosine / sine, -kMaxCotangent, kMaxCotangent);
}

}  // namespace

Eigen::SparseMatrix<double> mesh_laplacian(const std::vector<std::array<std::uint32_t, 3>>& tris,
                                           const Eigen::MatrixX3d& positions,
                                           LaplacianWeights weights) {
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(tris.size() * 12);
  for (const auto& f : tris) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = f[k], j = f[(k + 1) % 3], o = f[(k + 2) % 3];
      // The corner o faces the edge (i, j); each interior edge collects both opposite corners.
      // Uniform weights give 1/2 per triangle, so 1 per edge shared by two triangles.
      const double w = weights == LaplacianWeights::kUniform
                           ? 0.5
                           : cotangent(positions.row(o).transpose(), positions.row(i).transpose(),
                                       positions.row(j).transpose());
      t.emplace_back(i, j, w);
      t.emplace_back(j, i, w);
      t.emplace_back(i, i, -w);
      t.emplace_back(j, j, -w);
    }
  }
  const auto n = static_cast<Eigen::Index>(positions.rows());
  Eigen::SparseMatrix<double> l(n, n);
  l.setFromTriplets(t.begin(), t.end());
  return l;
}

Eigen::VectorXd one_ring_areas(const std::vector<std::array<std::uint32_t, 3>>& tris,
                               const Eigen::MatrixX3d& positions) {
  Eigen::VectorXd area = Eigen::VectorXd::Zero(positions.rows());
  for (const auto& f : tris) {
    const Eigen::Vector3d a = positions.row(f[0]), b = positions.row(f[1]), c = positions.row(f[2]);
    const double s = 0.5 * (b - a).cross(c - a).norm();
    for (const std::uint32_t i : f) area[i] += s;
  }
  return area;
}

}  // namespace fspm::stages
