#pragma once
// Laplacian mesh contraction (Au et al. 2008, sec. 4; the contraction Pirk 2013, 5.2.1, builds
// on). Each iteration solves, in the least-squares sense, the system
//   [ W_L L ] V' = [    0    ]
//   [  W_H  ]      [ W_H V   ]
// for the new positions V': the Laplacian rows pull every vertex toward the weighted mean of its
// neighbours (removing the surface's curvature, so tubes shrink onto their axes), the attraction
// rows W_H hold it to where it was. Then W_L is multiplied by s_L and each W_H,i becomes
// W_H,i^0 sqrt(A_i^0 / A_i) with the one-ring areas A_i, so that vertices already contracted stay
// put. The iteration stops when the surface area has fallen to `area_ratio_stop` of the start,
// after `max_iterations`, or at the first step that does not shrink the area (numerical failure
// once the mesh is degenerate; that step is discarded). The normal equations (L^T W_L^2 L + W_H^2)
// V' = W_H^2 V are solved by a sparse Cholesky (LDL^T) factorization, one per iteration, for the
// three coordinates at once.
#include <Eigen/Core>
#include <vector>

#include "stages/branch_mesh.hpp"
#include "stages/mesh_laplacian.hpp"

namespace fspm::stages {

struct ContractionParams {
  LaplacianWeights weights = LaplacianWeights::kCotangent;
  // W_L^0. The cotangent Laplacian and W_H are both free of units, so the contraction does not
  // depend on the mesh's scale; Au et al. give 1e-3 sqrt(A) (A the mean face area) for their
  // meshes, whose scale they do not state. 1 halves a tube's radius in about two iterations.
  double initial_contraction_weight = 1.0;
  double contraction_scale = 2.0;          // s_L (Au et al.: 2 to 3)
  double initial_attraction_weight = 1.0;  // W_H,i^0
  // Au et al. stop at a volume ratio of 1e-6; tubes are lines well before that (at 1e-4 a tube's
  // vertices lie within 2 % of its radius from the axis), and the area, unlike the volume, is
  // defined for meshes of separate, intersecting tubes.
  double area_ratio_stop = 1e-4;
  int max_iterations = 20;
  void validate() const;  // throws ValueError for values out of range
};

struct Contraction {
  Eigen::MatrixX3d positions;  // contracted, one row per vertex of the mesh
  int iterations = 0;
  double area_ratio = 1.0;  // final surface area over the initial one
};

// Throws ValueError for a mesh with a degenerate (zero-area) surface.
Contraction contract_mesh(const BranchMesh& mesh, const ContractionParams& params = {});

}  // namespace fspm::stages
