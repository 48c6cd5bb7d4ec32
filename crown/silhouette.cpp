#include "crown/silhouette.hpp"

#include <algorithm>
#include <cmath>

namespace fspm::crown {

std::vector<PixelClass> classify_pixels(const Mask& mask, Connectivity connectivity) {
  std::vector<PixelClass> out(mask.inside.size(), PixelClass::kOutside);
  const bool diagonals = connectivity == Connectivity::kFour;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      if (!mask.at(x, y)) continue;
      bool border = false;
      for (int dy = -1; dy <= 1 && !border; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || (!diagonals && dx != 0 && dy != 0)) continue;
          if (!mask.at(x + dx, y + dy)) {
            border = true;
            break;
          }
        }
      }
      out[static_cast<std::size_t>(y) * mask.width + x] =
          border ? PixelClass::kSilhouette : PixelClass::kInner;
    }
  }
  return out;
}

Eigen::Vector2d silhouette_point(const Mask& mask, const Raster& coverage, int x, int y) {
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      if (!mask.at(x + dx, y + dy)) normal += Eigen::Vector2d(dx, dy);
    }
  }
  const Eigen::Vector2d centre(x, y);
  if (normal.squaredNorm() == 0.0) return centre;  // outside pixels all around: no direction
  normal.normalize();
  auto cover = [&](int qx, int qy) {
    if (coverage.values.empty()) return mask.at(qx, qy) ? 1.0 : 0.0;
    return coverage.contains(qx, qy) ? static_cast<double>(coverage.at(qx, qy)) : 0.0;
  };
  double offset = cover(x, y) - 0.5;
  const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
  for (int k = 0; k < 4; ++k) {
    const double along = normal.dot(Eigen::Vector2d(dx[k], dy[k]));
    if (along > 0.0 && !mask.at(x + dx[k], y + dy[k])) {
      offset += cover(x + dx[k], y + dy[k]) * along * along;
    }
  }
  return centre + std::clamp(offset, 0.0, 1.0) * normal;
}

}  // namespace fspm::crown
