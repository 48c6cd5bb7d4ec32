#include "crown/relief.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <vector>

#include "crown/gaussian_blur.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {

void ReliefOptions::validate() const {
  if (levels < 1) throw ValueError("relief: levels (of the blur pyramid) must be >= 1");
}

Raster luminance_heightfield(const Raster& rgb, const Mask& mask, const ReliefOptions& options) {
  options.validate();
  if (mask.count() == 0) throw ValueError("the crown mask has no crown pixel");
  Raster lum = luminance_of(rgb);
  float lo = 1.0f, hi = 0.0f;
  for (int y = 0; y < lum.height; ++y) {
    for (int x = 0; x < lum.width; ++x) {
      if (!mask.at(x, y)) continue;
      lo = std::min(lo, lum.at(x, y));
      hi = std::max(hi, lum.at(x, y));
    }
  }
  // A crown of one colour has no relief: below an 8-bit step, differences are rounding of the
  // blurs and synthesis, which normalizing would blow up to the full range.
  constexpr float kFlat = 1e-3f;
  const float range = hi - lo > kFlat ? hi - lo : 1.0f;
  if (hi - lo <= kFlat) lo = hi;
  for (float& v : lum.values) v = std::clamp((v - lo) / range, 0.0f, 1.0f);
  Raster sum(lum.width, lum.height, 1);
  double sigma = options.first_sigma_px, total_weight = 0.0;
  for (int level = 0; level < options.levels; ++level, sigma *= 2.0) {
    const Raster blurred = masked_gaussian_blur(lum, mask, sigma);
    const auto weight = static_cast<float>(1 << level);  // coarser levels weigh more
    for (std::size_t i = 0; i < sum.values.size(); ++i) sum.values[i] += weight * blurred.values[i];
    total_weight += weight;
  }
  for (float& v : sum.values) v = static_cast<float>(v / total_weight);
  return sum;
}

Raster paste_on_plane(const Raster& height, const Mask& mask) {
  std::vector<int> unknown(mask.inside.size(), -1);
  int n = 0;
  for (std::size_t p = 0; p < mask.inside.size(); ++p) {
    if (mask.inside[p]) unknown[p] = n++;
  }
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      const int row = unknown[static_cast<std::size_t>(y) * mask.width + x];
      if (row < 0) continue;
      triplets.emplace_back(row, row, 4.0);
      for (int k = 0; k < 4; ++k) {
        const int qx = x + dx[k], qy = y + dy[k];
        // Guidance gradient v_pq = H_p - H_q (H taken as constant past the raster border).
        rhs[row] +=
            height.at(x, y) - (height.contains(qx, qy) ? height.at(qx, qy) : height.at(x, y));
        if (mask.at(qx, qy))
          triplets.emplace_back(row, unknown[static_cast<std::size_t>(qy) * mask.width + qx], -1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(a);
  if (solver.info() != Eigen::Success) throw ValueError("the relief system could not be factored");
  const Eigen::VectorXd x = solver.solve(rhs);
  Raster out(height.width, height.height, 1);
  for (std::size_t p = 0; p < unknown.size(); ++p) {
    if (unknown[p] >= 0) out.values[p] = static_cast<float>(x[unknown[p]]);
  }
  return out;
}

Raster relief(const Raster& rgb, const Mask& mask, const ReliefOptions& options) {
  return paste_on_plane(luminance_heightfield(rgb, mask, options), mask);
}

}  // namespace fspm::crown
