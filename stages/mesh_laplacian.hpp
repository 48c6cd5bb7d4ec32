#pragma once
// The Laplacian of a triangle mesh for the contraction of Au et al. 2008 (eq. 1 there):
// L_ij = w_ij for an edge (i, j), L_ii = -sum_j w_ij, with the cotangent weights
// w_ij = cot(alpha_ij) + cot(beta_ij) of the two angles opposite the edge, or uniform weights
// w_ij = 1. The one-ring areas A_i (sum of the areas of the triangles around i) drive the
// attraction weights of the contraction.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <vector>

#include "stages/branch_mesh.hpp"

namespace fspm::stages {

enum class LaplacianWeights { kCotangent, kUniform };

// Cotangents are clamped to [-kMaxCotangent, kMaxCotangent]: as the mesh contracts its triangles
// degenerate (angles near 0 or pi) and unclamped weights would swamp the system.
inline constexpr double kMaxCotangent = 1e4;

// The matrix has the same sparsity pattern for the same triangles whatever the positions
// (every edge and diagonal entry is stored, even when its weight is zero).
Eigen::SparseMatrix<double> mesh_laplacian(const std::vector<std::array<std::uint32_t, 3>>& tris,
                                           const Eigen::MatrixX3d& positions,
                                           LaplacianWeights weights);

// Sum of the areas of the triangles around each vertex.
Eigen::VectorXd one_ring_areas(const std::vector<std::array<std::uint32_t, 3>>& tris,
                               const Eigen::MatrixX3d& positions);

}  // namespace fspm::stages
