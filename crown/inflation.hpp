#pragma once
// Base crown shape by inflation (Argudo 4.3.2): the thin-plate energy (eq. 4.1) minimized on the
// pixel grid as a linear system for the 3D position of every inner pixel, with the 5x5 stencil of
// eq. 4.2 applied to x, y and z independently. Silhouette pixels are fixed on the crown's border
// in the plane z = 0 (Argudo: at (i, j, 0), their centres); pixels
// outside the crown that a stencil reaches (the outer silhouette S_o) are fixed at
// (i - d_i / 2, j - d_j / 2, -k), moved with the border: half way toward the pixel consulting them,
// so the surface leaves the silhouette with a near-vertical tangent. Solved with Eigen's
// SimplicialLDLT, the unknowns in nested dissection order (crown/nested_dissection.hpp).
#include <Eigen/Core>
#include <vector>

#include "crown/raster.hpp"
#include "crown/silhouette.hpp"

namespace fspm::crown {

struct InflationOptions {
  double k = 2.0;  // depth of the outer silhouette, pixels (Argudo Fig. 4.13 uses 2 and 8)
  Connectivity connectivity = Connectivity::kEight;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// The front half of the crown in pixel units: x = column, y = row (down), z >= 0 toward the
// viewer. vertex[pixel] is the index into positions, -1 outside the crown.
struct InflatedSheet {
  int width = 0;
  int height = 0;
  std::vector<PixelClass> classes;
  std::vector<int> vertex;
  std::vector<Eigen::Vector3d> positions;
};

// Silhouette pixels are placed on the crown's border (silhouette_point: half a pixel out from
// their centres), so the crown spans the mask's pixels edge to edge. With `coverage` (the mask
// was reduced from a finer one) the silhouette vertices are then moved to where the finer border
// passes, after the solve.
// Throws ValueError for an empty mask or k <= 0.
InflatedSheet inflate(const Mask& mask, const InflationOptions& options,
                      const Raster& coverage = Raster());

// The stencil M of eq. 4.2 at offset (dx, dy), |dx| + |dy| <= 2, else 0. Argudo prints 16 at the
// centre; 20 is the square of the 5-point Laplacian (the discrete thin-plate operator), whose rows
// sum to 0 so that a plane is a solution. We use 20.
double bilaplacian_weight(int dx, int dy);

}  // namespace fspm::crown
