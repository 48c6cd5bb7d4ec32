#include "environment/canopy_light.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace fspm::environment {

double cluster_extinction_per_m(const Sphere& cluster) {
  if (cluster.translucency <= 0.0) return std::numeric_limits<double>::infinity();
  return -std::log(cluster.translucency) / (2.0 * cluster.radius_m);
}

double cluster_leaf_area_m2(const Sphere& cluster) {
  const double r = cluster.radius_m;
  return cluster_extinction_per_m(cluster) / kSphericalLeafProjection * 4.0 / 3.0 *
         std::numbers::pi * r * r * r;
}

CanopyLight::CanopyLight(const Scene& scene, std::span<const Sphere> clusters, double voxel_m)
    : obstacles_(scene), clusters_(clusters.begin(), clusters.end()), dirs_(scene.sky.directions) {
  if (voxel_m > 0.0) grid_.emplace(clusters, voxel_m);
  scene.sky.validate();
  has_obstacles_ = !obstacles_.spheres.empty() || !obstacles_.boxes.empty() ||
                   !obstacles_.meshes.empty() || obstacles_.ground.has_value();
  mu_.reserve(clusters_.size());
  reach2_.reserve(clusters_.size());
  for (const Sphere& c : clusters_) {
    mu_.push_back(cluster_extinction_per_m(c));
    // A path through a sphere is at most its diameter, so a cluster removes at most (1 - gamma)
    // of the light in its cap, as in eq. 4.3: the same shadow volume bounds it.
    reach2_.push_back(shadow_reach2(c.radius_m, c.translucency, scene.sky.significance));
  }
  // The cos^2 sky of eq. 4.3, or a real sky's light (sky_distribution.hpp).
  const std::vector<double> w = sky_weights(scene.sky, dirs_);
  weight_.resize(dirs_.size());
  Eigen::Vector3d open = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    weight_[i] = w[static_cast<std::size_t>(i)];
    weight_sum_ += weight_[i];
    open += weight_[i] * dirs_.direction(i);
  }
  if (open.norm() > 0.0) open_direction_ = open.normalized();
}

// Optical depth per direction: mu times the path from p to the sphere's far side inside every
// cluster the ray crosses (from p itself when p lies inside).
void CanopyLight::accumulate_depth(const Eigen::Vector3d& p, std::uint32_t ignore,
                                   std::vector<double>& depth) const {
  depth.assign(dirs_.size(), 0.0);
  if (grid_ && ignore == kNoSphere) {
    for (int i = 0; i < dirs_.size(); ++i) depth[i] = grid_->optical_depth(p, dirs_.direction(i));
    return;
  }
  for (std::uint32_t j = 0; j < clusters_.size(); ++j) {
    if (j == ignore || mu_[j] == 0.0) continue;
    const Eigen::Vector3d v = clusters_[j].center - p;
    const double r = clusters_[j].radius_m;
    const double d2 = v.squaredNorm(), r2 = r * r;
    if (d2 < r2) {
      for (int i = 0; i < dirs_.size(); ++i) {
        const double b = dirs_.direction(i).dot(v);
        depth[i] += mu_[j] * (b + std::sqrt(r2 - d2 + b * b));
      }
      continue;
    }
    if (v.z() + r <= 0.0 || d2 > reach2_[j]) continue;
    const double dist = std::sqrt(d2);
    dirs_.for_each_in_cap(v / dist, std::sqrt(1.0 - r2 / d2), [&](int i) {
      const double b = dirs_.direction(i).dot(v);
      const double q = r2 - d2 + b * b;
      if (b > 0.0 && q > 0.0) depth[i] += mu_[j] * 2.0 * std::sqrt(q);
    });
  }
}

// The obstacles as in eq. 4.3: each crossed once multiplies by its translucency.
double CanopyLight::obstacle_transmission(const Eigen::Vector3d& p,
                                          const Eigen::Vector3d& d) const {
  const Scene& s = obstacles_;
  double t = 1.0;
  if (s.ground && p.z() < s.ground->height_m) t *= s.ground->translucency;
  for (const Sphere& o : s.spheres) {
    if (ray_hits_sphere(p, d, o.center, o.radius_m)) t *= o.translucency;
  }
  for (const Box& b : s.boxes) {
    if (b.ray_entry(p, d) >= 0.0) t *= b.translucency;
  }
  for (const TriangleMesh& m : s.meshes) {
    const int n = m.crossings(p, d);
    if (n > 0) t *= std::pow(m.translucency, n);
  }
  return t;
}

void CanopyLight::obstacle_visibility(const Eigen::Vector3d& p, std::vector<double>& vis) const {
  vis.assign(dirs_.size(), 1.0);
  if (!has_obstacles_) return;
  for (int i = 0; i < dirs_.size(); ++i) vis[i] = obstacle_transmission(p, dirs_.direction(i));
}

void CanopyLight::transmission(const Eigen::Vector3d& p, std::uint32_t ignore,
                               std::vector<double>& out) const {
  thread_local std::vector<double> depth;
  accumulate_depth(p, ignore, depth);
  obstacle_visibility(p, out);
  for (int i = 0; i < dirs_.size(); ++i) out[i] *= std::exp(-depth[i]);
}

double CanopyLight::transmission_along(const Eigen::Vector3d& p, const Eigen::Vector3d& d,
                                       std::uint32_t ignore) const {
  if (grid_ && ignore == kNoSphere) {
    const double t = std::exp(-grid_->optical_depth(p, d));
    return has_obstacles_ ? t * obstacle_transmission(p, d) : t;
  }
  double depth = 0.0;
  for (std::uint32_t j = 0; j < clusters_.size(); ++j) {
    if (j == ignore || mu_[j] == 0.0) continue;
    const Eigen::Vector3d v = clusters_[j].center - p;
    const double r = clusters_[j].radius_m;
    const double b = v.dot(d), q = b * b - v.squaredNorm() + r * r;
    if (q <= 0.0) continue;
    const double exit = b + std::sqrt(q);
    if (exit <= 0.0) continue;
    depth += mu_[j] * (exit - std::max(0.0, b - std::sqrt(q)));
  }
  const double t = std::exp(-depth);
  return has_obstacles_ ? t * obstacle_transmission(p, d) : t;
}

LightSample CanopyLight::evaluate(const Eigen::Vector3d& p, std::uint32_t ignore) const {
  thread_local std::vector<double> depth, vis;
  accumulate_depth(p, ignore, depth);
  obstacle_visibility(p, vis);
  double sum = 0.0;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    const double w = weight_[i] * vis[i] * std::exp(-depth[i]);
    sum += w;
    moment += w * dirs_.direction(i);
  }
  LightSample out;
  out.light = weight_sum_ > 0.0 ? sum / weight_sum_ : 0.0;
  out.direction = moment.norm() > 0.0 ? moment.normalized() : open_direction_;
  return out;
}

std::vector<LightSample> CanopyLight::evaluate_clusters() const {
  std::vector<LightSample> out(clusters_.size());
  for (std::uint32_t j = 0; j < clusters_.size(); ++j) out[j] = evaluate(clusters_[j].center);
  return out;
}

std::vector<LightSample> CanopyLight::evaluate_cluster_tops() const {
  std::vector<LightSample> out(clusters_.size());
  for (std::uint32_t j = 0; j < clusters_.size(); ++j) {
    out[j] = evaluate(cluster_top(clusters_[j]), j);
  }
  return out;
}

void CanopyLight::transmission_along(std::span<const Eigen::Vector3d> points,
                                     const Eigen::Vector3d& d,
                                     std::span<const std::uint32_t> ignore,
                                     std::span<double> out) const {
  if (grid_ && ignore.empty()) {
    for (std::size_t k = 0; k < points.size(); ++k) out[k] = transmission_along(points[k], d);
    return;
  }
  // Plane coordinates normal to d; cells of the largest cluster diameter.
  const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  double r_max = 0.0;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Sphere& c : clusters_) {
    r_max = std::max(r_max, c.radius_m);
    const Eigen::Vector2d q(c.center.dot(e1), c.center.dot(e2));
    lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  }
  // The shadows reach r_max beyond the centres.
  lo.array() -= r_max;
  hi.array() += r_max;
  if (clusters_.empty()) {
    for (std::size_t k = 0; k < points.size(); ++k) {
      out[k] = has_obstacles_ ? obstacle_transmission(points[k], d) : 1.0;
    }
    return;
  }
  // At most 1024 cells a side, however far apart the clusters are.
  const double cell = std::max({2.0 * r_max, (hi - lo).maxCoeff() / 1024.0, 1e-6});
  const Eigen::Vector2i n = (((hi - lo) / cell).array().floor().cast<int>() + 1).max(1).matrix();
  const auto cell_of = [&](double u, double v, int& i, int& j) {
    i = static_cast<int>(std::floor((u - lo.x()) / cell));
    j = static_cast<int>(std::floor((v - lo.y()) / cell));
  };
  // CSR of the cells each cluster's shadow square touches (two passes: count, fill).
  std::vector<std::uint32_t> start(static_cast<std::size_t>(n.x()) * n.y() + 1, 0), items;
  for (int pass = 0; pass < 2; ++pass) {
    for (std::uint32_t k = 0; k < clusters_.size(); ++k) {
      if (mu_[k] == 0.0) continue;
      const Sphere& c = clusters_[k];
      const double u = c.center.dot(e1), v = c.center.dot(e2);
      int i0, j0, i1, j1;
      cell_of(u - c.radius_m, v - c.radius_m, i0, j0);
      cell_of(u + c.radius_m, v + c.radius_m, i1, j1);
      for (int i = std::max(i0, 0); i <= std::min(i1, n.x() - 1); ++i) {
        for (int j = std::max(j0, 0); j <= std::min(j1, n.y() - 1); ++j) {
          const std::size_t at = static_cast<std::size_t>(i) * n.y() + j;
          if (pass == 0) {
            ++start[at + 1];
          } else {
            items[start[at]++] = k;
          }
        }
      }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
      items.resize(start.back());
    } else {
      for (std::size_t c = start.size() - 1; c > 0; --c) start[c] = start[c - 1];
      start[0] = 0;
    }
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d& p = points[k];
    const std::uint32_t skip = ignore.empty() ? kNoSphere : ignore[k];
    int i, j;
    cell_of(p.dot(e1), p.dot(e2), i, j);
    double depth = 0.0;
    if (i >= 0 && j >= 0 && i < n.x() && j < n.y()) {
      const std::size_t at = static_cast<std::size_t>(i) * n.y() + j;
      for (std::uint32_t m = start[at]; m < start[at + 1]; ++m) {
        const std::uint32_t c = items[m];
        if (c == skip) continue;
        const Eigen::Vector3d v = clusters_[c].center - p;
        const double r = clusters_[c].radius_m;
        const double b = v.dot(d), q = b * b - v.squaredNorm() + r * r;
        if (q <= 0.0) continue;
        const double exit = b + std::sqrt(q);
        if (exit <= 0.0) continue;
        depth += mu_[c] * (exit - std::max(0.0, b - std::sqrt(q)));
      }
    }
    out[k] = std::exp(-depth) * (has_obstacles_ ? obstacle_transmission(p, d) : 1.0);
  }
}

double CanopyLight::leaf_area_index_above(const Eigen::Vector3d& p, std::uint32_t ignore) const {
  double lai = 0.0;
  for (std::uint32_t j = 0; j < clusters_.size(); ++j) {
    if (j == ignore || mu_[j] == 0.0) continue;
    const Eigen::Vector3d& c = clusters_[j].center;
    const double r = clusters_[j].radius_m;
    const double h2 = (c.x() - p.x()) * (c.x() - p.x()) + (c.y() - p.y()) * (c.y() - p.y());
    if (h2 >= r * r) continue;
    const double half = std::sqrt(r * r - h2);
    // The vertical chord is [c.z - half, c.z + half]; its part above p.
    const double path = std::max(0.0, c.z() + half - std::max(p.z(), c.z() - half));
    lai += mu_[j] / kSphericalLeafProjection * path;
  }
  return lai;
}

double CanopyLight::sky_leaf_area_index_above(const Eigen::Vector3d& p,
                                              std::uint32_t ignore) const {
  thread_local std::vector<double> depth;
  accumulate_depth(p, ignore, depth);
  double sum = 0.0;
  for (int i = 0; i < dirs_.size(); ++i) {
    sum += weight_[i] * depth[i] * dirs_.direction(i).z();
  }
  return weight_sum_ > 0.0 ? sum / weight_sum_ / kSphericalLeafProjection : 0.0;
}

}  // namespace fspm::environment
