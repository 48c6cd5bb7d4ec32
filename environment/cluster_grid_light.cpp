#include "environment/cluster_grid_light.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "environment/sky_distribution.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// Margin around the buds when the grid is sized, so that bending crowns rarely outgrow it.
constexpr double kMargin_m = 0.5;

std::vector<std::unique_ptr<ShadowGrid>>& grid_pool() {
  thread_local std::vector<std::unique_ptr<ShadowGrid>> pool;
  return pool;
}

// The grid's light direction d tilts from the lean's axis; combine_sky_and_grid adds its tilt to
// the sky's mean direction, which already leans toward the sun, so the axis' own lean is taken
// out: the same tilt (tangents per axis) about the zenith.
Eigen::Vector3d tilt_about_zenith(const Eigen::Vector3d& d, const Eigen::Vector3d& axis) {
  return Eigen::Vector3d(d.x() / d.z() - axis.x() / axis.z(), d.y() / d.z() - axis.y() / axis.z(),
                         1.0)
      .normalized();
}

}  // namespace

ShadowGridParams cluster_grid_params() {
  // Twice the growth model's voxel (ShadowGridParams defaults), the same reach (4 x 0.3 m against
  // 8 x 0.15 m) and fall-off per metre (4 per voxel against 2). Shade per bud and per obstacle
  // voxel were fitted so that the clusters of the 30-year presets A and B, alone and 2 m from a
  // tall wall, get on average the light the fine grid gives them (within 0.03).
  ShadowGridParams p;
  p.voxel_size_m = 0.3;
  p.depth_voxels = 4;
  p.shade_b = 4.0;
  p.shade_a = 0.6;
  p.obstacle_shade = 0.5;
  return p;
}

ClusterGridLight::ClusterGridLight(const ShadowGridParams& params, const Scene& scene)
    : scene_(scene) {
  auto& pool = grid_pool();
  if (pool.empty()) {
    grid_ = std::make_unique<ShadowGrid>(params);
  } else {
    grid_ = std::move(pool.back());
    pool.pop_back();
    grid_->set_params(params);
  }
  // Under a real sky the pyramids lean along its PAR-weighted mean direction, as growth's do
  // (growth_model.cpp), so an occluder shades the clusters on its side away from the sun.
  if (scene.sky.distribution) {
    grid_->set_light_direction(scene.sky.distribution->mean_direction());
    leaning_ = true;
  }
}

ClusterGridLight::~ClusterGridLight() {
  constexpr std::size_t kKept = 2;  // grids kept per thread
  if (auto& pool = grid_pool(); pool.size() < kKept) pool.push_back(std::move(grid_));
}

void ClusterGridLight::fit(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  if (sized_ && grid_->covers(lo, hi)) {
    grid_->clear_buds();
    return;
  }
  // Room for the crown to bend: a tenth of its extent and kMargin_m on every side.
  const Eigen::Vector3d margin = (0.1 * (hi - lo)).array() + kMargin_m;
  grid_->reset(lo - margin, hi + margin);
  grid_->add_obstacles(scene_);
  grid_->keep_obstacles();
  sized_ = true;
}

void ClusterGridLight::evaluate(std::span<const Eigen::Vector3d> buds,
                                std::span<const std::uint32_t> bud_start,
                                std::span<const Eigen::Vector3d> centers,
                                std::span<const std::uint8_t> alive, std::span<double> light,
                                std::span<Eigen::Vector3d> direction) {
  const std::size_t nc = centers.size();
  Eigen::AlignedBox3d box;
  for (std::size_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    box.extend(centers[c]);
    for (std::uint32_t b = bud_start[c]; b < bud_start[c + 1]; ++b) box.extend(buds[b]);
  }
  if (box.isEmpty()) return;
  fit(box.min(), box.max());
  // Each bud's corners are found once, for its shade and for its light.
  corners_.resize(buds.size());
  located_.resize(buds.size());
  for (std::size_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    for (std::uint32_t b = bud_start[c]; b < bud_start[c + 1]; ++b) {
      located_[b] = grid_->locate(buds[b], corners_[b]);
      if (located_[b]) grid_->add_bud_spread(corners_[b]);
    }
  }
  grid_->propagate();
  for (std::size_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    const std::uint32_t first = bud_start[c], end = bud_start[c + 1];
    if (end > first) {
      double sum = 0.0;
      for (std::uint32_t b = first; b < end; ++b) {
        sum += located_[b] ? grid_->spread_bud_light(corners_[b]) : 1.0;
      }
      light[c] = sum / static_cast<double>(end - first);
    } else {
      light[c] = grid_->spread_bud_light(centers[c]);
    }
    direction[c] = grid_->spread_light_direction(centers[c]);
    if (leaning_) direction[c] = tilt_about_zenith(direction[c], grid_->light_axis());
  }
}

}  // namespace fspm::environment
