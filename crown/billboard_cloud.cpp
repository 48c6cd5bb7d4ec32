#include "crown/billboard_cloud.hpp"

#include <algorithm>

#include "crown/radius_cubemap.hpp"

namespace fspm::crown {

std::vector<Eigen::Vector3f> blue_noise_ball(std::mt19937_64& rng) {
  std::vector<Eigen::Vector3f> out;
  for (int level = 1; level <= 3; ++level) {
    const int cells = 1 << level;
    const float side = 2.0f / static_cast<float>(cells);
    std::uniform_real_distribution<float> offset(-side, side);
    for (int i = 0; i < cells; ++i) {
      for (int j = 0; j < cells; ++j) {
        for (int k = 0; k < cells; ++k) {
          const Eigen::Vector3f centre(-1.0f + side * (i + 0.5f), -1.0f + side * (j + 0.5f),
                                       -1.0f + side * (k + 0.5f));
          const Eigen::Vector3f p = centre + Eigen::Vector3f(offset(rng), offset(rng), offset(rng));
          if (p.squaredNorm() <= 1.0f) out.push_back(p);
        }
      }
    }
  }
  return out;
}

std::vector<Eigen::Vector3f> progressive_order(std::vector<Eigen::Vector3f> points,
                                               std::size_t fixed) {
  fixed = std::min(fixed, points.size());
  // sum[k]: summed distance of point k (not yet placed) to the free points placed so far.
  std::vector<double> sum(points.size(), 0.0);
  for (std::size_t i = fixed; i < points.size(); ++i) {
    std::size_t best = i;
    for (std::size_t k = i + 1; k < points.size(); ++k) {
      if (sum[k] > sum[best]) best = k;
    }
    std::swap(points[i], points[best]);
    std::swap(sum[i], sum[best]);
    for (std::size_t k = i + 1; k < points.size(); ++k) {
      sum[k] += static_cast<double>((points[k] - points[i]).norm());
    }
  }
  return points;
}

std::vector<Eigen::Vector3f> billboard_centres(const Cubemap& radius, const Eigen::Vector3f& centre,
                                               std::mt19937_64& rng) {
  float largest = 0.0f;
  for (const Raster& f : radius.faces) {
    for (float r : f.values) largest = std::max(largest, r);
  }
  constexpr std::size_t kLevelOneCells = 8;  // blue_noise_ball's first points, when kept
  const std::vector<Eigen::Vector3f> ball = blue_noise_ball(rng);
  std::vector<Eigen::Vector3f> out;
  std::size_t fixed = 0;
  for (std::size_t i = 0; i < ball.size(); ++i) {
    const Eigen::Vector3f q = largest * ball[i];
    if (q.squaredNorm() != 0.0f && q.norm() > sample(radius, q)) continue;
    out.push_back(centre + q);
    // The level-1 points come first from blue_noise_ball: the first up to eight kept are within
    // its first eight points.
    if (i < kLevelOneCells) fixed = out.size();
  }
  return progressive_order(std::move(out), fixed);
}

}  // namespace fspm::crown
