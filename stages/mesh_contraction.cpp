#include "stages/mesh_contraction.hpp"

#include <Eigen/SparseCholesky>
#include <cmath>
#include <string>

#include "fspm/error.hpp"

namespace fspm::stages {

void ContractionParams::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw ValueError(std::string(name) + " must be a positive number, got " + std::to_string(v));
    }
  };
  positive(initial_contraction_weight, "the initial contraction weight W_L");
  positive(initial_attraction_weight, "the initial attraction weight W_H");
  positive(area_ratio_stop, "the area ratio at which contraction stops");
  if (!(contraction_scale >= 1.0)) {
    throw ValueError("the contraction scale s_L must be at least 1, got " +
                     std::to_string(contraction_scale));
  }
  if (max_iterations < 1) throw ValueError("the contraction needs at least one iteration");
}

Contraction contract_mesh(const BranchMesh& mesh, const ContractionParams& params) {
  params.validate();
  const auto n = static_cast<Eigen::Index>(mesh.vertices.size());
  Contraction out;
  out.positions.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) out.positions.row(i) = mesh.vertices[i].transpose();
  const Eigen::VectorXd area0 = one_ring_areas(mesh.triangles, out.positions);
  const double total0 = area0.sum();
  if (!(total0 > 0.0)) throw ValueError("the mesh has no surface area to contract");
  // A one ring contracted to nothing counts as this small area, so its W_H stays finite.
  const double floor_area = total0 / static_cast<double>(n) * 1e-12;
  Eigen::VectorXd w_h = Eigen::VectorXd::Constant(n, params.initial_attraction_weight);
  double w_l = params.initial_contraction_weight;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  Eigen::Index pattern_nonzeros = -1;
  for (int it = 0; it < params.max_iterations; ++it) {
    const Eigen::SparseMatrix<double> l =
        mesh_laplacian(mesh.triangles, out.positions, params.weights);
    Eigen::SparseMatrix<double> a = (w_l * w_l) * (l.transpose() * l);
    const Eigen::VectorXd w_h2 = w_h.cwiseProduct(w_h);
    for (Eigen::Index i = 0; i < n; ++i) a.coeffRef(i, i) += w_h2[i];
    // The pattern of L (hence of the system) stays the same, so the ordering is computed once.
    if (a.nonZeros() != pattern_nonzeros) solver.analyzePattern(a);
    pattern_nonzeros = a.nonZeros();
    solver.factorize(a);
    if (solver.info() != Eigen::Success) break;  // numerically singular: keep the last positions
    const Eigen::MatrixX3d next = solver.solve(w_h2.asDiagonal() * out.positions);
    if (!next.allFinite()) break;
    const Eigen::VectorXd area = one_ring_areas(mesh.triangles, next);
    // Once the tubes are lines their triangles are degenerate and the system ill-conditioned; a
    // step that gives area back has failed numerically, and the last positions are kept.
    if (area.sum() / total0 > out.area_ratio) break;
    out.positions = next;
    out.iterations = it + 1;
    out.area_ratio = area.sum() / total0;
    if (out.area_ratio < params.area_ratio_stop) break;
    w_l *= params.contraction_scale;
    for (Eigen::Index i = 0; i < n; ++i) {
      w_h[i] =
          params.initial_attraction_weight * std::sqrt(area0[i] / std::max(area[i], floor_area));
    }
  }
  return out;
}

}  // namespace fspm::stages
