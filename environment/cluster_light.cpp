#include "environment/cluster_light.hpp"

#include "environment/sky_distribution.hpp"

#include "environment/analytic_caps.hpp"
#include "environment/sky_occlusion_kernel.hpp"
#include "fspm/dcheck.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fspm::environment {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Obstacle visibility is recomputed after the cluster moved this share of its distance to the
// nearest obstacle (about 3 degrees of parallax), at least kMinObstacleMove_m.
constexpr double kObstacleParallax = 0.05;
constexpr double kMinObstacleMove_m = 0.05;

double box_distance(const Box& b, const Eigen::Vector3d& p) {
  const Eigen::Vector3d local = b.rotation.transpose() * (p - b.center);
  return (local.cwiseAbs() - b.half_extent).cwiseMax(0.0).norm();
}

}  // namespace

ClusterLightField::ClusterLightField(int directions, double significance,
                                     const Eigen::Vector3d& brightest)
    : dirs_(directions), significance_(significance) {
  brightest_ =
      brightest.norm() > 0 ? Eigen::Vector3d(brightest.normalized()) : Eigen::Vector3d::UnitZ();
  weight_.resize(static_cast<std::size_t>(dirs_.size()));
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    const double c = dirs_.direction(i).dot(brightest_);
    weight_[i] = c * c;  // Pirk eq. 4.3: I = cos^2(angle to the brightest point)
    weight_sum_ += weight_[i];
    m += weight_[i] * dirs_.direction(i);
  }
  open_direction_ = m.norm() > 0 ? Eigen::Vector3d(m.normalized()) : Eigen::Vector3d::UnitZ();
  vis_.resize(weight_.size());
  for (int i = 0; i < dirs_.size(); ++i) {
    xs_.push_back(static_cast<float>(dirs_.direction(i).x()));
    ys_.push_back(static_cast<float>(dirs_.direction(i).y()));
    zs_.push_back(static_cast<float>(dirs_.direction(i).z()));
  }
}

void ClusterLightField::set_sky_distribution(std::shared_ptr<const SkyDistribution> distribution) {
  Sky sky;
  sky.directions = dirs_.size();
  sky.significance = significance_;
  apply_sky_distribution(sky, std::move(distribution));
  distribution_ = sky.distribution;
  significance_ = sky.significance;
  brightest_ = sky.brightest;
  const std::vector<double> w = sky_weights(sky, dirs_);
  weight_sum_ = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    weight_[static_cast<std::size_t>(i)] = w[static_cast<std::size_t>(i)];
    weight_sum_ += weight_[static_cast<std::size_t>(i)];
    m += weight_[static_cast<std::size_t>(i)] * dirs_.direction(i);
  }
  open_direction_ = m.norm() > 0 ? Eigen::Vector3d(m.normalized()) : Eigen::Vector3d::UnitZ();
}

void ClusterLightField::set_clusters(std::span<const Eigen::Vector3d> centers,
                                     std::span<const double> radii,
                                     std::span<const double> translucency) {
  const std::size_t n = centers.size();
  center_.assign(centers.begin(), centers.end());
  radius_.assign(radii.begin(), radii.end());
  gamma_.assign(translucency.begin(), translucency.end());
  reach2_.resize(n);
  reach_.resize(n);
  max_reach_ = 0.0;
  max_radius_ = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    reach2_[c] = shadow_reach2(radius_[c], gamma_[c], significance_);
    reach_[c] = reach2_[c] >= 0.0 ? std::sqrt(reach2_[c]) : 0.0;
    if (std::isfinite(reach2_[c])) max_reach_ = std::max(max_reach_, reach_[c]);
    max_radius_ = std::max(max_radius_, radius_[c]);
  }
  alive_.assign(n, 1);
  light_.assign(n, 1.0);
  direction_.assign(n, open_direction_);
  neighbors_.assign(n, {});
  external_.assign(n, nullptr);
  external_offset_.assign(n, 0);
  listed_.assign(n, 0);
  grid_stale_ = true;
  obstacle_vis_.assign(n, {});
  sky_share_.assign(n, 1.0);
  sky_direction_.assign(n, open_direction_);
  obstacle_at_ = center_;
  obstacle_tolerance2_.assign(n, kInf);
}

void ClusterLightField::set_obstacles(const Scene& scene) {
  obstacles_ = Scene{};
  obstacles_.boxes = scene.boxes;
  obstacles_.meshes = scene.meshes;
  for (auto& m : obstacles_.meshes) m.update_bounds();
  obstacles_.spheres = scene.spheres;
  obstacles_.ground = scene.ground;
  has_obstacles_ = !obstacles_.boxes.empty() || !obstacles_.meshes.empty() ||
                   !obstacles_.spheres.empty() || obstacles_.ground.has_value();
  // The sky directions in every box's frame, converted once: the boxes do not move, and every
  // visibility ray of every cluster uses one of these directions.
  const auto n = static_cast<std::size_t>(dirs_.size());
  box_rays_.clear();
  std::vector<Eigen::Vector3d> local(n);
  for (const Box& b : obstacles_.boxes) {
    for (std::size_t i = 0; i < n; ++i) {
      local[i] = b.local_direction(dirs_.direction(static_cast<int>(i)));
    }
    box_rays_.emplace_back(local);
  }
  box_hit_.assign(n, 0);
}

void ClusterLightField::obstacle_visibility(const Eigen::Vector3d& p, std::vector<float>& vis,
                                            double& distance) const {
  const int n = dirs_.size();
  vis.assign(static_cast<std::size_t>(n), 1.0f);
  distance = kInf;
  bool any = false;
  if (obstacles_.ground) {
    const Ground& g = *obstacles_.ground;
    distance = std::min(distance, std::abs(p.z() - g.height_m));
    if (p.z() < g.height_m && g.translucency < 1.0) {
      for (float& v : vis) v *= static_cast<float>(g.translucency);
      any = true;
    }
  }
  const auto cast = [&](const Eigen::Vector3d& centre, double r, auto&& hit) {
    const Eigen::Vector3d d = centre - p;
    const double dist = d.norm();
    if (dist <= r) {
      for (int i = 0; i < n; ++i) hit(i);
    } else {
      dirs_.for_each_in_cap(d / dist, std::sqrt(dist * dist - r * r) / dist, hit);
    }
  };
  for (std::size_t k = 0; k < obstacles_.boxes.size(); ++k) {
    const Box& b = obstacles_.boxes[k];
    distance = std::min(distance, box_distance(b, p));
    if (b.translucency >= 1.0 || b.top_z() <= p.z()) continue;
    const auto g = static_cast<float>(b.translucency);
    // Box::ray_entry with the point converted once and every direction's slab test in one
    // branch-free pass (BoxRayDirections); the bounding cap still picks the directions used.
    box_rays_[k].hits(b, b.to_local(p), box_hit_);
    cast(b.center, b.bounding_radius(), [&](int i) {
      if (box_hit_[static_cast<std::size_t>(i)] != 0) {
        vis[static_cast<std::size_t>(i)] *= g;
        any = true;
      }
    });
  }
  for (const Sphere& s : obstacles_.spheres) {
    distance = std::min(distance, std::max(0.0, (s.center - p).norm() - s.radius_m));
    if (s.translucency >= 1.0 || s.center.z() + s.radius_m <= p.z()) continue;
    const auto g = static_cast<float>(s.translucency);
    cast(s.center, s.radius_m, [&](int i) {
      if (ray_hits_sphere(p, dirs_.direction(i), s.center, s.radius_m)) {
        vis[static_cast<std::size_t>(i)] *= g;
        any = true;
      }
    });
  }
  for (const TriangleMesh& m : obstacles_.meshes) {
    distance = std::min(distance, std::max(0.0, (m.center - p).norm() - m.bounding_radius_m));
    if (m.translucency >= 1.0 || m.center.z() + m.bounding_radius_m <= p.z()) continue;
    cast(m.center, m.bounding_radius_m, [&](int i) {
      const int k = m.crossings(p, dirs_.direction(i));
      if (k > 0) {
        vis[static_cast<std::size_t>(i)] *= static_cast<float>(std::pow(m.translucency, k));
        any = true;
      }
    });
  }
  if (!any) vis.clear();
}

bool ClusterLightField::obstacles_stale(std::uint32_t c) const {
  return has_obstacles_ && (center_[c] - obstacle_at_[c]).squaredNorm() > obstacle_tolerance2_[c];
}

double ClusterLightField::sky_light(std::uint32_t c, Eigen::Vector3d& direction) const {
  direction = sky_direction_[c];
  return sky_share_[c];
}

void ClusterLightField::update_sky_light(std::uint32_t c) {
  const std::vector<float>& vis = obstacle_vis_[c];
  if (vis.empty()) {
    sky_direction_[c] = open_direction_;
    sky_share_[c] = 1.0;
    return;
  }
  double sum = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < vis.size(); ++i) {
    const double w = vis[i] * weight_[i];
    sum += w;
    m += w * dirs_.direction(static_cast<int>(i));
  }
  sky_direction_[c] = m.norm() > 1e-300 ? Eigen::Vector3d(m.normalized()) : open_direction_;
  sky_share_[c] = weight_sum_ > 0 ? std::clamp(sum / weight_sum_, 0.0, 1.0) : 0.0;
}

bool ClusterLightField::update_obstacles(std::uint32_t c) {
  double distance = kInf;
  obstacle_visibility(center_[c], scratch_vis_, distance);
  obstacle_at_[c] = center_[c];
  const double tol = std::max(kMinObstacleMove_m, kObstacleParallax * distance);
  obstacle_tolerance2_[c] = std::isfinite(tol) ? tol * tol : kInf;
  const bool changed = scratch_vis_ != obstacle_vis_[c];
  if (changed) {
    std::swap(scratch_vis_, obstacle_vis_[c]);
    update_sky_light(c);
  }
  return changed;
}

double ClusterLightField::loss_bound(std::uint32_t j, const Eigen::Vector3d& d) const {
  const double d2 = d.squaredNorm();
  // Outside the shadow volume or entirely below the point's horizon: no shade.
  if (d2 > reach2_[j] || d.z() + radius_[j] <= 0.0) return 0.0;
  const double r2 = radius_[j] * radius_[j];
  if (d2 <= r2) return 1.0 - gamma_[j];
  return std::min(1.0, 3.0 * (1.0 - gamma_[j]) * (1.0 - std::sqrt((d2 - r2) / d2)));
}

void ClusterLightField::rebuild_grid() {
  grid_stale_ = false;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf), hi = -lo;
  std::size_t count = 0;
  for (std::size_t c = 0; c < center_.size(); ++c) {
    if (!alive_[c]) continue;
    lo = lo.cwiseMin(center_[c]);
    hi = hi.cwiseMax(center_[c]);
    ++count;
  }
  cell_items_.clear();
  if (count == 0 || !lo.allFinite() || !hi.allFinite()) {
    grid_n_.setZero();
    cell_start_.assign(1, 0);
    return;
  }
  const Eigen::Vector3d extent = (hi - lo).cwiseMax(1e-6);
  cell_ = std::max(0.5 * (max_reach_ + kListMargin_m), extent.maxCoeff() / 48.0);
  grid_lo_ = lo;
  grid_n_ = (extent / cell_).array().floor().cast<int>().matrix() + Eigen::Vector3i::Ones();
  const std::size_t cells = static_cast<std::size_t>(grid_n_.prod());
  cell_start_.assign(cells + 1, 0);
  const auto id_of = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3i q = ((p - grid_lo_) / cell_)
                                  .array()
                                  .floor()
                                  .cast<int>()
                                  .max(0)
                                  .min(grid_n_.array() - 1)
                                  .matrix();
    return (static_cast<std::size_t>(q.z()) * grid_n_.y() + q.y()) * grid_n_.x() + q.x();
  };
  for (std::size_t c = 0; c < center_.size(); ++c) {
    if (alive_[c]) ++cell_start_[id_of(center_[c]) + 1];
  }
  for (std::size_t k = 0; k < cells; ++k) cell_start_[k + 1] += cell_start_[k];
  cell_items_.resize(count);
  std::vector<std::uint32_t>& fill = scratch_fill_;
  fill.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t c = 0; c < center_.size(); ++c) {
    if (alive_[c]) cell_items_[fill[id_of(center_[c])]++] = static_cast<std::uint32_t>(c);
  }
}

void ClusterLightField::add_occluder(std::uint32_t c, std::uint32_t j, const Eigen::Vector3d& d,
                                     double& all) {
  // Does j shade c? Inside its shadow volume and not entirely below c's horizon.
  const double d2 = d.squaredNorm();
  if (d2 > reach2_[j] || d.z() + radius_[j] <= 0.0) return;
  add_sphere_occluder(d, d2, radius_[j], gamma_[j], all, caps_);
  (void)c;
}

std::vector<ClusterNeighbor>& ClusterLightField::own_neighbor_list(std::uint32_t c) {
  std::vector<ClusterNeighbor>& list = neighbors_[c];
  if (external_[c] != nullptr) {
    const ListView view = neighbors(c);
    list.assign(view.begin(), view.end());
    for (ClusterNeighbor& e : list) e.index += view.offset;
    external_[c] = nullptr;
  }
  return list;
}

void ClusterLightField::gather_from_grid(std::uint32_t c, double& all) {
  if (grid_stale_) rebuild_grid();
  const Eigen::Vector3d p = center_[c];
  std::vector<ClusterNeighbor>& list = neighbors_[c];
  list.clear();
  external_[c] = nullptr;
  listed_[c] = 1;
  if (grid_n_.x() <= 0) return;
  const double range = max_reach_ + kListMargin_m;
  Eigen::Vector3i c0, c1;
  for (int k = 0; k < 3; ++k) {
    const auto clampi = [&](double x) {
      return static_cast<int>(std::clamp(std::floor((x - grid_lo_[k]) / cell_), 0.0,
                                         static_cast<double>(grid_n_[k] - 1)));
    };
    c0[k] = clampi(p[k] - range);
    c1[k] = clampi(p[k] + range);
  }
  const double own_reach = reach_[c];
  for (int z = c0.z(); z <= c1.z(); ++z) {
    for (int y = c0.y(); y <= c1.y(); ++y) {
      const std::size_t row = (static_cast<std::size_t>(z) * grid_n_.y() + y) * grid_n_.x();
      for (std::uint32_t k = cell_start_[row + c0.x()]; k < cell_start_[row + c1.x() + 1]; ++k) {
        const std::uint32_t j = cell_items_[k];
        if (j == c) continue;
        const Eigen::Vector3d d = center_[j] - p;
        // Listed when j may shade c (within its shadow reach, not below c's horizon) or c may
        // shade j, each widened by the margin.
        const double d2 = d.squaredNorm();
        const double lim_j = reach_[j] + kListMargin_m;
        const double lim_c = own_reach + kListMargin_m;
        const bool j_shades = d.z() + radius_[j] > -kListMargin_m && d2 <= lim_j * lim_j;
        const bool c_shades = -d.z() + radius_[c] > -kListMargin_m && d2 <= lim_c * lim_c;
        if (!j_shades && !c_shades) continue;
        list.push_back({j, d.cast<float>()});
        add_occluder(c, j, d, all);
      }
    }
  }
}

void ClusterLightField::evaluate(std::uint32_t c, bool rebuild) {
  ++evaluations_;
  const Eigen::Vector3d p = center_[c];
  caps_.clear();
  double all = 1.0;
  if (!listed_[c]) rebuild = true;
  // The list is a valid candidate set while no listed neighbour drifted by half the margin
  // (one that was farther than the margin would have to drift as far to matter).
  if (!rebuild) {
    const double half2 = 0.25 * kListMargin_m * kListMargin_m;
    const ListView view = neighbors(c);
    for (const ClusterNeighbor& e : view) {
      const Eigen::Vector3d d = center_[e.index + view.offset] - p;
      if ((d - e.relative.cast<double>()).squaredNorm() > half2) {
        rebuild = true;
        break;
      }
    }
  }
  if (rebuild) {
    gather_from_grid(c, all);
  } else {
    std::vector<ClusterNeighbor>& list = own_neighbor_list(c);
    for (ClusterNeighbor& e : list) {
      const std::uint32_t j = e.index;
      if (!alive_[j]) continue;
      const Eigen::Vector3d d = center_[j] - p;
      e.relative = d.cast<float>();
      add_occluder(c, j, d, all);
    }
  }
  const std::vector<float>& obstacle = obstacle_vis_[c];
  if (!distribution_ && obstacle.empty() && caps_.size() <= kMaxAnalyticCaps &&
      analytic_caps_exact(std::span<const Cap>(caps_))) {
    const AnalyticLight a = analytic_cap_light(brightest_, std::span<const Cap>(caps_));
    light_[c] = std::clamp(all * a.integral / a.open_integral, 0.0, 1.0);
    direction_[c] = a.moment.norm() > 1e-300 && light_[c] > 0
                        ? Eigen::Vector3d(a.moment.normalized())
                        : open_direction_;
    return;
  }
  const int n = dirs_.size();
  FSPM_DCHECK(obstacle.empty() || obstacle.size() == vis_.size(),
              "obstacle visibility holds one value per sky direction");
  if (obstacle.empty()) {
    std::fill(vis_.begin(), vis_.end(), static_cast<float>(all));
  } else {
    for (int i = 0; i < n; ++i) vis_[i] = static_cast<float>(all) * obstacle[i];
  }
  // Single precision: the cap tests of LightModel in double precision agree except for directions
  // within ~1e-7 of a cap's rim.
  const DirectionColumns<float> columns{xs_.data(), ys_.data(), zs_.data()};
  if (n <= 64) {
    // Few directions: all caps in one sweep while the directions stay in registers.
    occlude_by_caps(std::span<float>(vis_), columns,
                    occluding_caps(std::span<const Cap>(caps_), packed_caps_));
  } else {
    occlude_cap_rings(columns);
  }
  double sum = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const double w = vis_[i] * weight_[i];
    sum += w;
    m += w * dirs_.direction(i);
  }
  light_[c] = weight_sum_ > 0 ? std::clamp(sum / weight_sum_, 0.0, 1.0) : 0.0;
  direction_[c] = m.norm() > 1e-300 ? Eigen::Vector3d(m.normalized()) : open_direction_;
}

void ClusterLightField::occlude_cap_rings(DirectionColumns<float> columns) {
  const int rings = dirs_.ring_count();
  for (const Cap& cap : caps_) {
    // Only the rings whose (common) z lies within the cap's z range can hold covered cells;
    // rings are contiguous in index order from the zenith down.
    const double zc = cap.axis.z();
    const double sc = std::sqrt(std::max(0.0, 1.0 - zc * zc));
    const double z_lo = zc * cap.cos_a - sc * cap.sin_a - 1e-5;
    const double z_hi = zc > cap.cos_a ? 2.0 : zc * cap.cos_a + sc * cap.sin_a + 1e-5;
    int r0 = 0;
    while (r0 < rings && dirs_.ring_z(r0) > z_hi) ++r0;
    int r1 = r0;
    while (r1 < rings && dirs_.ring_z(r1) >= z_lo) ++r1;
    if (r1 == r0) continue;
    const int first = dirs_.ring_first(r0);
    const int last = dirs_.ring_first(r1 - 1) + dirs_.ring_size(r1 - 1);
    FSPM_DCHECK(0 <= first && first < last && last <= dirs_.size(),
                "a cap's rings are a range of the sky's directions");
    const OccludingCap<float> one = occluding_cap<float>(cap);
    occlude_by_caps(std::span<float>(vis_).subspan(first, last - first),
                    {columns.x + first, columns.y + first, columns.z + first}, {&one, 1});
  }
}

}  // namespace fspm::environment

namespace fspm::environment {

void ClusterLightField::evaluate_batch(std::span<const std::uint32_t> which,
                                       std::span<const std::uint8_t> relist) {
  Scene world = obstacles_;
  world.sky.brightest = brightest_;
  world.sky.directions = dirs_.size();
  world.sky.significance = significance_;
  world.sky.distribution = distribution_;
  if (distribution_) world.sky.analytic = false;
  // The per-cluster path samples the obstacles over the directions: the batch must compute the same
  // integral, so LightModel's closed-form boxes stay off here.
  world.sky.analytic_boxes = false;
  std::vector<std::uint32_t> sphere_of(center_.size(), kNoSphere);
  for (std::uint32_t c = 0; c < center_.size(); ++c) {
    if (!alive_[c]) continue;
    sphere_of[c] = static_cast<std::uint32_t>(world.spheres.size());
    world.spheres.push_back({center_[c], radius_[c], gamma_[c], false});
  }
  const LightModel model(world);
  for (const std::uint32_t c : which) {
    if (!alive_[c]) continue;
    ++evaluations_;
    const LightSample s = model.evaluate(center_[c], sphere_of[c]);
    light_[c] = s.light;
    direction_[c] = s.direction;
    if (!listed_[c] || (c < relist.size() && relist[c] != 0)) {
      double all = 1.0;
      gather_from_grid(c, all);
      caps_.clear();
      continue;
    }
    std::vector<ClusterNeighbor>& list = own_neighbor_list(c);
    for (ClusterNeighbor& e : list) e.relative = (center_[e.index] - center_[c]).cast<float>();
  }
}

}  // namespace fspm::environment
