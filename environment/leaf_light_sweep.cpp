// Leaf light model "sweep": CanopySweep (canopy_sweep.hpp), the turbid medium swept once per sky
// direction through voxels of kCanopySweepVoxel_m: its cost is the voxels times the directions,
// whatever the number of clusters, so a whole crown is evaluated again cheaply.
//
// Groups of clusters farther apart than the shadow reach of the sky's significance cutoff (eq. 4.3
// shadow volumes, light_model.hpp) are swept each in its own grid: far-apart crowns get the light
// they would get alone, and the grid does not span the empty space between them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <unordered_map>

#include "environment/canopy_sweep.hpp"
#include "environment/leaf_light_model.hpp"

namespace fspm::environment {
namespace {

// Union-find over cluster indices.
std::uint32_t find(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Component of every cluster: clusters whose cells (of the largest reach) touch are joined.
std::vector<std::uint32_t> components(std::span<const Sphere> clusters, double significance) {
  const std::size_t n = clusters.size();
  double reach = 0.0;
  for (const Sphere& c : clusters) {
    const double r2 = shadow_reach2(c.radius_m, c.translucency, significance);
    reach = std::max(reach, std::isfinite(r2) ? std::sqrt(std::max(r2, 0.0)) : 1e9);
  }
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  if (reach >= 1e9) return std::vector<std::uint32_t>(n, 0);  // no cutoff: one grid
  const double cell = std::max(reach, 1e-3);
  const auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
    return (static_cast<std::uint64_t>(x & 0x1FFFFF) << 42) |
           (static_cast<std::uint64_t>(y & 0x1FFFFF) << 21) |
           static_cast<std::uint64_t>(z & 0x1FFFFF);
  };
  std::unordered_map<std::uint64_t, std::uint32_t> first;
  std::vector<Eigen::Matrix<std::int64_t, 3, 1>> at(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    for (int j = 0; j < 3; ++j) {
      at[k][j] = static_cast<std::int64_t>(std::floor(clusters[k].center[j] / cell));
    }
    const auto [it, added] = first.try_emplace(key(at[k].x(), at[k].y(), at[k].z()), k);
    if (!added) parent[find(parent, k)] = find(parent, it->second);
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = first.find(key(at[k].x() + dx, at[k].y() + dy, at[k].z() + dz));
          if (it != first.end()) parent[find(parent, k)] = find(parent, it->second);
        }
      }
    }
  }
  std::vector<std::uint32_t> out(n);
  for (std::uint32_t k = 0; k < n; ++k) out[k] = find(parent, k);
  return out;
}

class SweepLeafLight final : public LeafLightModel {
 public:
  explicit SweepLeafLight(const Sky& sky)
      : sweep_(sky, kCanopySweepVoxel_m), significance_(sky.significance) {}

  void evaluate(std::span<const Sphere> clusters,
                std::span<const std::span<const float>> visibility,
                std::span<LightSample> out) override {
    const std::vector<std::uint32_t> group = components(clusters, significance_);
    std::vector<std::uint32_t> order(clusters.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return group[a] < group[b]; });
    for (std::size_t begin = 0; begin < order.size();) {
      std::size_t end = begin;
      spheres_.clear();
      centers_.clear();
      vis_.clear();
      while (end < order.size() && group[order[end]] == group[order[begin]]) {
        const std::uint32_t k = order[end++];
        spheres_.push_back(clusters[k]);
        centers_.push_back(clusters[k].center);
        if (!visibility.empty()) vis_.push_back(visibility[k]);
      }
      lit_.resize(spheres_.size());
      sweep_.evaluate(spheres_, centers_, vis_, lit_);
      for (std::size_t j = begin; j < end; ++j) out[order[j]] = lit_[j - begin];
      begin = end;
    }
  }

 private:
  CanopySweep sweep_;
  double significance_;
  std::vector<Sphere> spheres_;
  std::vector<Eigen::Vector3d> centers_;
  std::vector<std::span<const float>> vis_;
  std::vector<LightSample> lit_;
};

}  // namespace

std::unique_ptr<LeafLightModel> make_sweep_leaf_light(const Sky& sky) {
  return std::make_unique<SweepLeafLight>(sky);
}

}  // namespace fspm::environment
