#include "graphics/translucent_sort.hpp"

#include <algorithm>
#include <numeric>

namespace fspm::graphics {

std::vector<Eigen::Vector3f> soup_centroids(std::span<const Eigen::Vector3f> corners) {
  std::vector<Eigen::Vector3f> centroids(corners.size() / 3);
  for (std::size_t t = 0; t < centroids.size(); ++t) {
    centroids[t] = (corners[3 * t] + corners[3 * t + 1] + corners[3 * t + 2]) / 3.0f;
  }
  return centroids;
}

std::vector<std::uint32_t> back_to_front(std::span<const Eigen::Vector3f> centroids,
                                         const Eigen::Vector3f& eye) {
  std::vector<float> distance2(centroids.size());
  for (std::size_t t = 0; t < centroids.size(); ++t) {
    distance2[t] = (centroids[t] - eye).squaredNorm();
  }
  std::vector<std::uint32_t> order(centroids.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return distance2[a] > distance2[b]; });
  return order;
}

}  // namespace fspm::graphics
