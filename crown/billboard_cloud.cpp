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

std::vector<Eigen::Vector3f> billboard_centres(const Cubemap& radius, const Eigen::Vector3f& centre,
                                               std::mt19937_64& rng) {
  float largest = 0.0f;
  for (const Raster& f : radius.faces) {
    for (float r : f.values) largest = std::max(largest, r);
  }
  std::vector<Eigen::Vector3f> out;
  for (const Eigen::Vector3f& p : blue_noise_ball(rng)) {
    const Eigen::Vector3f q = largest * p;
    if (q.squaredNorm() == 0.0f || q.norm() <= sample(radius, q)) out.push_back(centre + q);
  }
  return out;
}

}  // namespace fspm::crown
