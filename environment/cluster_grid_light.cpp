#include "environment/cluster_grid_light.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// Margin around the buds when the grid is sized, so that bending crowns rarely outgrow it.
constexpr double kMargin_m = 0.5;

std::vector<std::unique_ptr<ShadowGrid>>& grid_pool() {
  thread_local std::vector<std::unique_ptr<ShadowGrid>> pool;
  return pool;
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

// The eight voxel centres around p with their trilinear weights (summing to 1), and whether each
// lies in the upper layer. At a voxel centre one weight is 1: Palubicki's grid exactly.
template <typename F>
void ClusterGridLight::for_each_corner(const Eigen::Vector3d& p, F&& f) const {
  const double h = grid_->params().voxel_size_m;
  const Eigen::Vector3d g = (p - grid_->origin()) / h - Eigen::Vector3d::Constant(0.5);
  const Eigen::Vector3d base = g.array().floor();
  const Eigen::Vector3d t = g - base;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d o(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    double w = 1.0;
    for (int a = 0; a < 3; ++a) w *= o[a] > 0 ? t[a] : 1.0 - t[a];
    f(grid_->origin() + (base + o + Eigen::Vector3d::Constant(0.5)) * h, w, o.z() > 0);
  }
}

void ClusterGridLight::add_bud(const Eigen::Vector3d& p) {
  for_each_corner(p, [this](const Eigen::Vector3d& q, double w, bool) {
    if (w > 0.0) grid_->add_bud(q, w);
  });
}

// Q / C interpolated between the eight voxel centres, each without the bud's own shade: its
// share a w_k of the corner's source, and for the lower corners the upper corners' shares one
// layer down (a / b times their weight, which every lower corner's pyramid takes in). A lone bud
// anywhere sees 1.
double ClusterGridLight::bud_light(const Eigen::Vector3d& p) const {
  const ShadowGridParams& gp = grid_->params();
  const double gz = (p.z() - grid_->origin().z()) / gp.voxel_size_m - 0.5;
  const double upper_weight = gz - std::floor(gz);
  double sum = 0.0;
  for_each_corner(p, [&](const Eigen::Vector3d& q, double w, bool upper) {
    if (w <= 0.0 || grid_->obstacle(q)) return;
    const double own = gp.shade_a * (w + (upper ? 0.0 : upper_weight / gp.shade_b));
    const double s = grid_->shade(q) - own;
    sum += w * std::min(std::max(gp.full_light - s, 0.0) / gp.full_light, 1.0);
  });
  return sum;
}

Eigen::Vector3d ClusterGridLight::light_direction(const Eigen::Vector3d& p) const {
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for_each_corner(p, [&](const Eigen::Vector3d& q, double w, bool) {
    if (w > 0.0) d += w * grid_->light_direction(q);
  });
  return d.normalized();
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
  for (std::size_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    for (std::uint32_t b = bud_start[c]; b < bud_start[c + 1]; ++b) add_bud(buds[b]);
  }
  grid_->propagate();
  for (std::size_t c = 0; c < nc; ++c) {
    if (!alive[c]) continue;
    const std::uint32_t first = bud_start[c], end = bud_start[c + 1];
    if (end > first) {
      double sum = 0.0;
      for (std::uint32_t b = first; b < end; ++b) sum += bud_light(buds[b]);
      light[c] = sum / static_cast<double>(end - first);
    } else {
      light[c] = bud_light(centers[c]);
    }
    direction[c] = light_direction(centers[c]);
  }
}

}  // namespace fspm::environment
