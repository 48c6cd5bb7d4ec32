#include "environment/light_model.hpp"

#include "environment/analytic_caps.hpp"
#include "environment/sky_occlusion_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fspm::environment {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The scene, once its sky is checked: the direction set is built from it before the body runs.
const Scene& with_checked_sky(const Scene& scene) {
  scene.sky.validate();
  return scene;
}

}  // namespace

double shadow_reach2(double r, double g, double significance) {
  if (g >= 1.0) return -1.0;
  if (significance <= 0.0) return kInf;
  const double q = significance / (3.0 * (1.0 - g));
  if (q >= 1.0) return -1.0;
  const double cos_min = 1.0 - q;
  const double sin2_min = 1.0 - cos_min * cos_min;
  return r * r / sin2_min;
}

LightModel::LightModel(const Scene& scene)
    : scene_(with_checked_sky(scene)), dirs_(scene.sky.directions) {
  set_sky_weights();
  for (auto& mesh : scene_.meshes) mesh.update_bounds();
  if (!scene_.boxes.empty()) build_fine_directions();
  set_shadow_reaches();
  if (!all_spheres_.empty()) build_sphere_index();
}

void LightModel::set_sky_weights() {
  // Pirk: I = cos^2(angle to the brightest point), or a real sky's light (sky_distribution.hpp).
  const std::vector<double> w = sky_weights(scene_.sky, dirs_);
  weight_.resize(dirs_.size());
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    weight_[i] = w[static_cast<std::size_t>(i)];
    weight_sum_ += weight_[i];
    m += weight_[i] * dirs_.direction(i);
  }
  open_direction_ = m.norm() > 0 ? Eigen::Vector3d(m.normalized()) : Eigen::Vector3d::UnitZ();
}

void LightModel::set_shadow_reaches() {
  const double eps = scene_.sky.significance;
  reach2_.resize(scene_.spheres.size());
  for (std::size_t i = 0; i < scene_.spheres.size(); ++i) {
    const auto& s = scene_.spheres[i];
    reach2_[i] = shadow_reach2(s.radius_m, s.translucency, eps);
    if (reach2_[i] >= 0) all_spheres_.push_back(static_cast<std::uint32_t>(i));
  }
  for (const auto& box : scene_.boxes) {
    box_reach2_.push_back(shadow_reach2(box.bounding_radius(), box.translucency, eps));
  }
  for (const auto& mesh : scene_.meshes) {
    mesh_reach2_.push_back(shadow_reach2(mesh.bounding_radius_m, mesh.translucency, eps));
  }
}

void LightModel::sphere_volume_box(std::uint32_t i, double clamp, Eigen::Vector3d& lo,
                                   Eigen::Vector3d& hi) const {
  const auto& s = scene_.spheres[i];
  const double r = std::min(std::sqrt(reach2_[i]), clamp);
  lo = s.center - Eigen::Vector3d(r, r, r);
  hi = s.center + Eigen::Vector3d(r, r, s.radius_m);
}

void LightModel::build_sphere_index() {
  // The grid covers every shadow volume, unbounded ones clamped to a margin around the spheres;
  // points outside the grid fall back to visiting every sphere, which is always correct.
  std::vector<double> finite;
  bool any_infinite = false;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(kInf), hi = -lo;
  for (const std::uint32_t i : all_spheres_) {
    const auto& s = scene_.spheres[i];
    lo = lo.cwiseMin(s.center - Eigen::Vector3d::Constant(s.radius_m));
    hi = hi.cwiseMax(s.center + Eigen::Vector3d::Constant(s.radius_m));
    if (std::isinf(reach2_[i])) {
      any_infinite = true;
    } else {
      finite.push_back(std::sqrt(reach2_[i]));
    }
  }
  const double max_finite = finite.empty() ? 0.0 : *std::max_element(finite.begin(), finite.end());
  const double clamp = any_infinite ? std::max(max_finite, (hi - lo).norm()) : max_finite;
  grid_lo_ = Eigen::Vector3d::Constant(kInf);
  grid_hi_ = -grid_lo_;
  for (const std::uint32_t i : all_spheres_) {
    Eigen::Vector3d a, z;
    sphere_volume_box(i, clamp, a, z);
    grid_lo_ = grid_lo_.cwiseMin(a);
    grid_hi_ = grid_hi_.cwiseMax(z);
  }
  if (!choose_index_cell(finite, clamp)) return;
  fill_sphere_index(clamp);
}

bool LightModel::choose_index_cell(std::vector<double>& finite, double clamp) {
  const Eigen::Vector3d extent = (grid_hi_ - grid_lo_).cwiseMax(1e-9);
  if (!finite.empty()) {
    std::nth_element(finite.begin(), finite.begin() + finite.size() / 2, finite.end());
    cell_ = 0.5 * finite[finite.size() / 2];
  } else {
    cell_ = extent.maxCoeff() / 16.0;
  }
  cell_ = std::max(cell_, extent.maxCoeff() / 128.0);
  if (!extent.allFinite() || !std::isfinite(cell_) || cell_ <= 0.0) {
    return false;  // degenerate coordinates: no grid, every query visits every sphere
  }
  auto cells_of = [&](double h) {
    return (extent / h).array().ceil().min(1 << 20).max(1.0).cast<int>().matrix().eval();
  };
  // Keep the index within a few million entries.
  for (;;) {
    const Eigen::Vector3i g = cells_of(cell_);
    double entries = 0.0;
    for (const std::uint32_t i : all_spheres_) {
      Eigen::Vector3d a, z;
      sphere_volume_box(i, clamp, a, z);
      entries += ((z - a) / cell_ + Eigen::Vector3d::Constant(2.0)).prod();
    }
    if (g.cast<double>().prod() <= (1 << 21) && entries <= 8e6) break;
    cell_ *= 1.5;
    if (!std::isfinite(cell_)) {
      grid_n_.setZero();
      return false;
    }
  }
  grid_n_ = cells_of(cell_);
  return true;
}

void LightModel::fill_sphere_index(double clamp) {
  auto cell_range = [&](std::uint32_t i, Eigen::Vector3i& c0, Eigen::Vector3i& c1) {
    Eigen::Vector3d a, z;
    sphere_volume_box(i, clamp, a, z);
    // Clamped as doubles before the cast: a far-away bound would overflow int.
    auto cell_of = [&](double x, int k) {
      const double c = std::floor((x - grid_lo_[k]) / cell_);
      return static_cast<int>(std::clamp(c, 0.0, static_cast<double>(grid_n_[k] - 1)));
    };
    for (int k = 0; k < 3; ++k) {
      c0[k] = cell_of(a[k], k);
      c1[k] = cell_of(z[k], k);
    }
  };
  const std::size_t cells = static_cast<std::size_t>(grid_n_.prod());
  cell_start_.assign(cells + 1, 0);
  auto cell_id = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * grid_n_.y() + y) * grid_n_.x() + x;
  };
  // Two passes over the volumes (CSR): count per cell, then place.
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      for (std::size_t c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
      cell_items_.resize(cell_start_[cells]);
      fill.assign(cell_start_.begin(), cell_start_.end() - 1);
    }
    for (const std::uint32_t i : all_spheres_) {
      Eigen::Vector3i c0, c1;
      cell_range(i, c0, c1);
      for (int z = c0.z(); z <= c1.z(); ++z) {
        for (int y = c0.y(); y <= c1.y(); ++y) {
          for (int x = c0.x(); x <= c1.x(); ++x) {
            const std::size_t id = cell_id(x, y, z);
            if (pass == 0) {
              ++cell_start_[id + 1];
            } else {
              cell_items_[fill[id]++] = i;
            }
          }
        }
      }
    }
  }
}

bool LightModel::box_relevant(std::size_t i, const Eigen::Vector3d& p) const {
  const Box& b = scene_.boxes[i];
  if (box_reach2_[i] < 0 || b.top_z() <= p.z()) return false;
  return (b.center - p).squaredNorm() <= box_reach2_[i];
}

bool LightModel::mesh_relevant(std::size_t i, const Eigen::Vector3d& p) const {
  const auto& m = scene_.meshes[i];
  return mesh_reach2_[i] >= 0 && m.center.z() + m.bounding_radius_m > p.z() &&
         (m.center - p).squaredNorm() <= mesh_reach2_[i];
}

LightSample LightModel::evaluate(const Eigen::Vector3d& p, std::uint32_t ignore) const {
  thread_local std::vector<Cap> caps;
  caps.clear();
  double all = 1.0;
  if (scene_.ground && p.z() < scene_.ground->height_m) all *= scene_.ground->translucency;

  std::span<const std::uint32_t> candidates = all_spheres_;
  if (grid_n_.x() > 0) {
    const Eigen::Vector3d u = (p - grid_lo_) / cell_;
    // Test the range in floating point first: casting a far-away (or NaN) coordinate to int is
    // undefined behaviour.
    const bool inside = u.x() >= 0.0 && u.y() >= 0.0 && u.z() >= 0.0 && u.x() < grid_n_.x() &&
                        u.y() < grid_n_.y() && u.z() < grid_n_.z();
    if (inside) {
      const int x = static_cast<int>(u.x());
      const int y = static_cast<int>(u.y());
      const int z = static_cast<int>(u.z());
      const std::size_t id = (static_cast<std::size_t>(z) * grid_n_.y() + y) * grid_n_.x() + x;
      candidates = std::span<const std::uint32_t>(cell_items_.data() + cell_start_[id],
                                                  cell_start_[id + 1] - cell_start_[id]);
    }
  }
  for (const std::uint32_t i : candidates) {
    if (i == ignore) continue;
    const Sphere& s = scene_.spheres[i];
    if (s.center.z() + s.radius_m <= p.z()) continue;  // entirely below p's horizon
    const Eigen::Vector3d d = s.center - p;
    const double d2 = d.squaredNorm();
    if (d2 > reach2_[i]) continue;  // outside the shadow volume
    add_sphere_occluder(d, d2, s.radius_m, s.translucency, all, caps);
  }
  bool boxes = false;
  for (std::size_t i = 0; i < scene_.boxes.size() && !boxes; ++i) boxes = box_relevant(i, p);
  for (std::size_t i = 0; i < scene_.meshes.size() && !boxes; ++i) boxes = mesh_relevant(i, p);

  if (scene_.sky.analytic && !scene_.sky.distribution && scene_.sky.analytic_boxes && boxes) {
    LightSample out;
    if (analytic_with_boxes(p, caps, all, out)) return out;
  }
  if (scene_.sky.analytic && !scene_.sky.distribution && !boxes &&
      caps.size() <= kMaxAnalyticCaps && analytic_caps_exact(std::span<const Cap>(caps))) {
    const AnalyticLight a = analytic_cap_light(scene_.sky.brightest, std::span<const Cap>(caps));
    LightSample out;
    out.light = std::clamp(all * a.integral / a.open_integral, 0.0, 1.0);
    out.direction = a.moment.norm() > 1e-300 && out.light > 0
                        ? Eigen::Vector3d(a.moment.normalized())
                        : open_direction_;
    return out;
  }
  return sampled(p, caps, all, boxes);
}

LightSample LightModel::sampled(const Eigen::Vector3d& p, std::span<const Cap> caps,
                                double all_factor, bool boxes) const {
  thread_local std::vector<double> vis;
  vis.assign(dirs_.size(), all_factor);
  const int n = dirs_.size();
  const DirectionColumns<double> columns{dirs_.xs().data(), dirs_.ys().data(), dirs_.zs().data()};
  if (n <= 128) {
    // Few directions: every cap takes one branch-free pass over all of them, all caps in one
    // sweep while the directions stay in registers.
    thread_local std::vector<OccludingCap<double>> packed;
    occlude_by_caps(vis, columns, occluding_caps(caps, packed));
    return finish(p, vis, boxes);
  }
  for (const Cap& c : caps) {
    // A wide cap: one branch-free vectorized pass over all cells is cheaper than rasterizing ring
    // by ring. Both use the same exact test d . axis >= cos(alpha).
    if (c.cos_a < 0.97) {
      const OccludingCap<double> one = occluding_cap<double>(c);
      occlude_by_caps(vis, columns, {&one, 1});
    } else {
      const double g = c.gamma;
      dirs_.for_each_in_cap(c.axis, c.cos_a, [&](int i) { vis[i] *= g; });
    }
  }
  return finish(p, vis, boxes);
}

LightSample LightModel::finish(const Eigen::Vector3d& p, std::vector<double>& vis,
                               bool boxes) const {
  if (boxes) {
    for (std::size_t k = 0; k < scene_.boxes.size(); ++k) {
      if (!box_relevant(k, p)) continue;
      const Box& b = scene_.boxes[k];
      const Eigen::Vector3d d = b.center - p;
      const double dist = d.norm();
      const double r = b.bounding_radius();
      auto hit = [&](int i) {
        if (b.ray_entry(p, dirs_.direction(i)) >= 0.0) vis[i] *= b.translucency;
      };
      if (dist <= r) {
        for (int i = 0; i < dirs_.size(); ++i) hit(i);
      } else {
        dirs_.for_each_in_cap(d / dist, std::sqrt(dist * dist - r * r) / dist, hit);
      }
    }
    apply_meshes(p, vis);
  }
  double sum = 0.0;
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    const double w = vis[i] * weight_[i];
    sum += w;
    m += w * dirs_.direction(i);
  }
  LightSample out;
  out.light = weight_sum_ > 0 ? std::clamp(sum / weight_sum_, 0.0, 1.0) : 0.0;
  out.direction = m.norm() > 1e-300 ? Eigen::Vector3d(m.normalized()) : open_direction_;
  return out;
}

void LightModel::apply_meshes(const Eigen::Vector3d& p, std::vector<double>& vis) const {
  for (std::size_t k = 0; k < scene_.meshes.size(); ++k) {
    if (!mesh_relevant(k, p)) continue;
    const auto& m = scene_.meshes[k];
    const Eigen::Vector3d d = m.center - p;
    const double dist = d.norm();
    const double r = m.bounding_radius_m;
    auto hit = [&](int i) {
      const int n = m.crossings(p, dirs_.direction(i));
      if (n > 0) vis[i] *= std::pow(m.translucency, n);
    };
    if (dist <= r) {
      for (int i = 0; i < dirs_.size(); ++i) hit(i);
    } else {
      dirs_.for_each_in_cap(d / dist, std::sqrt(dist * dist - r * r) / dist, hit);
    }
  }
}

void LightModel::evaluate(std::span<const Eigen::Vector3d> points,
                          std::span<LightSample> out) const {
  for (std::size_t i = 0; i < points.size() && i < out.size(); ++i) out[i] = evaluate(points[i]);
}

LightSample LightModel::evaluate_brute_force(const Eigen::Vector3d& p) const {
  std::vector<double> vis(dirs_.size(), 1.0);
  for (int i = 0; i < dirs_.size(); ++i) {
    const Eigen::Vector3d& d = dirs_.direction(i);
    if (scene_.ground && p.z() < scene_.ground->height_m) vis[i] *= scene_.ground->translucency;
    for (const auto& s : scene_.spheres) {
      if (ray_hits_sphere(p, d, s.center, s.radius_m)) vis[i] *= s.translucency;
    }
    for (const auto& b : scene_.boxes) {
      if (b.ray_entry(p, d) >= 0.0) vis[i] *= b.translucency;
    }
    for (const auto& m : scene_.meshes) {
      const int n = m.crossings(p, d);
      if (n > 0) vis[i] *= std::pow(m.translucency, n);
    }
  }
  return finish(p, vis, false);
}

}  // namespace fspm::environment
