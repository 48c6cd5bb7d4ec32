#include "environment/shadow_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm::environment {
namespace {

constexpr double kMaxVoxels = 6e7;  // about 1.5 GB of grid buffers

// For each world axis, the box axis that lies along it, when every box axis lies along a world
// axis (rotation entries 0 or +-1: axis-aligned boxes and walls along x or y); else -1.
Eigen::Vector3i world_to_box_axes(const Eigen::Matrix3d& rotation) {
  Eigen::Vector3i axis(-1, -1, -1);
  for (int a = 0; a < 3; ++a) {
    int along = -1;
    for (int w = 0; w < 3; ++w) {
      const double r = rotation(w, a);
      if (r == 0.0) continue;
      if (std::abs(r) != 1.0 || along >= 0) return Eigen::Vector3i(-1, -1, -1);
      along = w;
    }
    if (along < 0 || axis[along] >= 0) return Eigen::Vector3i(-1, -1, -1);
    axis[along] = a;
  }
  return axis;
}

}  // namespace

ShadowGrid::ShadowGrid(const ShadowGridParams& params) { set_params(params); }

void ShadowGrid::set_params(const ShadowGridParams& params) {
  p_ = params;
  n_ = Eigen::Vector3i::Zero();
  if (!(p_.voxel_size_m > 0) || !(p_.shade_a > 0) || !(p_.shade_b > 1) || p_.depth_voxels < 0 ||
      !(p_.full_light > 0) || !(p_.obstacle_shade >= 0)) {
    throw ValueError(
        "shadow grid: expected voxel_size_m > 0, shadow_a > 0, shadow_b > 1, "
        "shadow_depth_voxels >= 0 and full_light > 0");
  }
  lean_ = Eigen::Vector2d::Zero();  // a pooled grid does not keep a former sky's lean
  update_lean_shifts();
}

void ShadowGrid::set_light_direction(const Eigen::Vector3d& toward_light) {
  if (!toward_light.allFinite() || !(toward_light.z() > 0)) {
    throw ValueError("shadow grid: expected a light direction above the horizon (z > 0)");
  }
  Eigen::Vector2d lean = toward_light.head<2>() / toward_light.z();
  const double max_tan = std::tan(kMaxLeanDeg * 3.14159265358979323846 / 180.0);
  if (lean.norm() > max_tan) lean *= max_tan / lean.norm();
  lean_ = lean;
  n_ = Eigen::Vector3i::Zero();  // the margins change: reset() first
  update_lean_shifts();
}

void ShadowGrid::update_lean_shifts() {
  shift_x_.assign(p_.depth_voxels + 1, 0);
  shift_y_.assign(p_.depth_voxels + 1, 0);
  leaning_ = false;
  for (int q = 0; q <= p_.depth_voxels; ++q) {
    shift_x_[q] = static_cast<int>(std::lround(q * lean_.x()));
    shift_y_[q] = static_cast<int>(std::lround(q * lean_.y()));
    leaning_ = leaning_ || shift_x_[q] != 0 || shift_y_[q] != 0;
  }
}

void ShadowGrid::voxel_span(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                            Eigen::Vector3d& first, Eigen::Vector3d& last) const {
  const double h = p_.voxel_size_m;
  const int reach = p_.depth_voxels + 1;
  // Shade comes from up to the last layer's shift further toward the light.
  const int sx = shift_x_.back(), sy = shift_y_.back();
  first = (lo / h).array().floor() -
          Eigen::Array3d(reach + std::max(0, -sx), reach + std::max(0, -sy), 1);
  last = (hi / h).array().floor() +
         Eigen::Array3d(reach + std::max(0, sx), reach + std::max(0, sy), reach);
}

void ShadowGrid::reset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  const double h = p_.voxel_size_m;
  // Voxels are aligned to multiples of h so that the same point always falls in the same voxel.
  Eigen::Vector3d first, last;
  voxel_span(lo, hi, first, last);
  const double voxels = (last - first + Eigen::Vector3d::Ones()).prod();
  if (!(voxels <= kMaxVoxels)) {
    throw ValueError(
        "shadow grid: the tree spans more than 6 x 10^7 voxels; use a larger "
        "voxel_size_m");
  }
  // Per voxel: source, shade, stamp, obstacle flag, the kept obstacle sources and the summed-area
  // table entry.
  constexpr double kBytesPerVoxel =
      4 * sizeof(double) + sizeof(std::uint32_t) + sizeof(std::uint8_t);
  check_memory(1.5 * voxels * kBytesPerVoxel,  // buffers grow by half again
               "a shadow grid of " + std::to_string(std::llround(voxels)) + " voxels");
  origin_ = first * h;
  n_ = (last - first).cast<int>() + Eigen::Vector3i::Ones();
  const std::size_t total = static_cast<std::size_t>(n_.x()) * n_.y() * n_.z();
  // Buffers only grow, and by half again, so a growing tree does not touch fresh memory every
  // cycle; only the used part is cleared.
  auto clear = [total](auto& v, auto value) {
    if (v.capacity() < total) v.reserve(total + total / 2);
    v.assign(total, value);
  };
  clear(source_, 0.0);
  clear(shade_, 0.0);
  clear(shade_stamp_, std::uint32_t{0});
  clear(obstacle_, std::uint8_t{0});
  stamp_ = 1;
  obstacle_source_.clear();
  touched_.clear();
  const std::size_t sat_total = static_cast<std::size_t>(n_.x() + 1) * (n_.y() + 1) * n_.z();
  // The first row and column of every layer stay zero; build_summed_area_tables() writes the rest.
  if (sat_.capacity() < sat_total) sat_.reserve(sat_total + sat_total / 2);
  sat_.assign(sat_total, 0.0);
}

void ShadowGrid::keep_obstacles() { obstacle_source_ = source_; }

void ShadowGrid::clear_buds() {
  // Only the voxels buds were added to changed since keep_obstacles().
  const bool kept = obstacle_source_.size() == source_.size();
  for (const std::size_t at : touched_) source_[at] = kept ? obstacle_source_[at] : 0.0;
  touched_.clear();
}

bool ShadowGrid::covers(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const {
  // The same voxel range reset() would choose for [lo, hi] must lie inside the grid.
  const double h = p_.voxel_size_m;
  Eigen::Vector3d first, last;
  voxel_span(lo, hi, first, last);
  const Eigen::Vector3d have = (origin_ / h).array().round();
  return n_.prod() > 0 && (first.array() >= have.array()).all() &&
         (last.array() < (have + n_.cast<double>()).array()).all();
}

Eigen::Vector3d ShadowGrid::voxel_center(int i, int j, int k) const {
  return origin_ + p_.voxel_size_m * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
}

bool ShadowGrid::voxel_of(const Eigen::Vector3d& p, Eigen::Vector3i& v) const {
  const Eigen::Vector3d f = ((p - origin_) / p_.voxel_size_m).array().floor();
  if (!f.allFinite()) return false;
  for (int a = 0; a < 3; ++a) {
    if (f[a] < 0 || f[a] >= n_[a]) return false;
    v[a] = static_cast<int>(f[a]);
  }
  return true;
}

void ShadowGrid::mark_obstacle(int i, int j, int k, double translucency, double fraction) {
  const std::size_t at = index(i, j, k);
  if (obstacle_[at]) return;  // a voxel casts the shade of one obstacle at most
  obstacle_[at] = 1;
  source_[at] +=
      p_.obstacle_shade * p_.full_light * (1.0 - std::clamp(translucency, 0.0, 1.0)) * fraction;
}

namespace {
// The first and last voxel index per axis of the box [lo, hi], clamped to a grid of n voxels of
// size h from origin.
std::pair<Eigen::Vector3i, Eigen::Vector3i> voxel_range(const Eigen::Vector3d& origin,
                                                        const Eigen::Vector3i& n, double h,
                                                        const Eigen::Vector3d& lo,
                                                        const Eigen::Vector3d& hi) {
  Eigen::Vector3i a, b;
  for (int d = 0; d < 3; ++d) {
    a[d] = std::max(0, static_cast<int>(std::floor((lo[d] - origin[d]) / h)));
    b[d] = std::min(n[d] - 1, static_cast<int>(std::floor((hi[d] - origin[d]) / h)));
  }
  return {a, b};
}

}  // namespace

template <typename Inside>
void ShadowGrid::fill_region(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                             double translucency, const Inside& inside) {
  // The share of a voxel an obstacle fills, from 4 x 4 x 4 sample points, so that a wall casts
  // shade in proportion to its thickness whatever its alignment to the grid.
  constexpr int kSamples = 4;
  const double h = p_.voxel_size_m;
  const auto [a, b] = voxel_range(origin_, n_, h, lo, hi);
  for (int k = a.z(); k <= b.z(); ++k) {
    for (int j = a.y(); j <= b.y(); ++j) {
      for (int i = a.x(); i <= b.x(); ++i) {
        const Eigen::Vector3d corner = origin_ + h * Eigen::Vector3d(i, j, k);
        int hits = 0;
        for (int s = 0; s < kSamples * kSamples * kSamples; ++s) {
          const Eigen::Vector3d f((s % kSamples + 0.5) / kSamples,
                                  (s / kSamples % kSamples + 0.5) / kSamples,
                                  (s / (kSamples * kSamples) + 0.5) / kSamples);
          hits += inside(corner + h * f) ? 1 : 0;
        }
        if (hits > 0)
          mark_obstacle(i, j, k, translucency, hits / double(kSamples * kSamples * kSamples));
      }
    }
  }
}

void ShadowGrid::fill_aligned_box(const Box& box, const Eigen::Vector3i& axes,
                                  const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  // fill_region's 4 x 4 x 4 samples for a box whose axes lie along the world axes: a sample's
  // box-frame coordinate along box axis axes[w] is exactly +-(its world coordinate w minus the
  // centre's), so it is inside when each of its three coordinates is, and a voxel's hits are the
  // product of the inside samples counted per axis (64 containment tests per voxel become 4 per
  // voxel row; the same counts, bit for bit).
  constexpr int kSamples = 4;
  const double h = p_.voxel_size_m;
  const auto [a, b] = voxel_range(origin_, n_, h, lo, hi);
  std::array<std::vector<int>, 3> inside;
  for (int w = 0; w < 3; ++w) {
    inside[w].assign(static_cast<std::size_t>(std::max(0, b[w] - a[w] + 1)), 0);
    const double half = box.half_extent[axes[w]];
    for (int v = a[w]; v <= b[w]; ++v) {
      const double corner = origin_[w] + h * v;
      for (int s = 0; s < kSamples; ++s) {
        const double x = corner + h * ((s + 0.5) / kSamples);
        inside[w][v - a[w]] += std::abs(x - box.center[w]) <= half ? 1 : 0;
      }
    }
  }
  for (int k = a.z(); k <= b.z(); ++k) {
    for (int j = a.y(); j <= b.y(); ++j) {
      for (int i = a.x(); i <= b.x(); ++i) {
        const int hits = inside[0][i - a.x()] * inside[1][j - a.y()] * inside[2][k - a.z()];
        if (hits > 0) {
          mark_obstacle(i, j, k, box.translucency, hits / double(kSamples * kSamples * kSamples));
        }
      }
    }
  }
}

void ShadowGrid::add_bud(const Eigen::Vector3d& p, double weight) {
  Eigen::Vector3i v;
  if (!voxel_of(p, v)) return;
  const std::size_t at = index(v.x(), v.y(), v.z());
  source_[at] += p_.shade_a * weight;
  touched_.push_back(at);
}

void ShadowGrid::add_obstacles(const Scene& scene) {
  for (const Box& b : scene.boxes) add_box(b);
  for (const Sphere& s : scene.spheres) add_sphere(s);
  for (const TriangleMesh& m : scene.meshes) add_mesh(m);
}

void ShadowGrid::add_box(const Box& box) {
  const Eigen::Vector3d reach = box.rotation.cwiseAbs() * box.half_extent;
  const Eigen::Vector3i axes = world_to_box_axes(box.rotation);
  if (axes.minCoeff() >= 0) {
    fill_aligned_box(box, axes, box.center - reach, box.center + reach);
    return;
  }
  fill_region(box.center - reach, box.center + reach, box.translucency,
              [&box](const Eigen::Vector3d& p) { return box.contains(p); });
}

void ShadowGrid::add_sphere(const Sphere& sphere) {
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(sphere.radius_m);
  const double r2 = sphere.radius_m * sphere.radius_m;
  fill_region(sphere.center - reach, sphere.center + reach, sphere.translucency,
              [&](const Eigen::Vector3d& p) { return (p - sphere.center).squaredNorm() <= r2; });
}

void ShadowGrid::add_mesh(const TriangleMesh& mesh) {
  // Triangles are sampled at a third of a voxel, so no voxel they cross is missed.
  const double step = p_.voxel_size_m / 3.0;
  for (const Eigen::Vector3i& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d e1 = mesh.vertices[t[1]] - a, e2 = mesh.vertices[t[2]] - a;
    const int n = std::max(1, static_cast<int>(std::ceil(std::max(e1.norm(), e2.norm()) / step)));
    if (n > 100000) throw ValueError("shadow grid: a mesh triangle spans more than 10^5 voxels");
    for (int u = 0; u <= n; ++u) {
      for (int w = 0; u + w <= n; ++w) {
        Eigen::Vector3i v;
        if (voxel_of(a + (u * e1 + w * e2) / n, v)) {
          mark_obstacle(v.x(), v.y(), v.z(), mesh.translucency, 1.0);
        }
      }
    }
  }
}

void ShadowGrid::build_summed_area_tables() {
  const int sx = n_.x() + 1, sy = n_.y() + 1;
  for (int k = 0; k < n_.z(); ++k) {
    double* layer = sat_.data() + static_cast<std::size_t>(k) * sx * sy;
    for (int j = 0; j < n_.y(); ++j) {
      const double* src = source_.data() + index(0, j, k);
      const double* above = layer + j * sx + 1;
      double* out = layer + (j + 1) * sx + 1;
      double row = 0.0;
      for (int i = 0; i < n_.x(); ++i) {
        row += src[i];
        out[i] = above[i] + row;
      }
    }
  }
}

double ShadowGrid::box_sum(int k, int i0, int i1, int j0, int j1) const {
  // Sum of source_ over layer k, i in [i0, i1], j in [j0, j1] (clipped to the grid).
  i0 = std::max(i0, 0);
  j0 = std::max(j0, 0);
  i1 = std::min(i1, n_.x() - 1);
  j1 = std::min(j1, n_.y() - 1);
  if (i0 > i1 || j0 > j1) return 0.0;
  const int sx = n_.x() + 1;
  const double* layer = sat_.data() + static_cast<std::size_t>(k) * sx * (n_.y() + 1);
  return layer[(j1 + 1) * sx + i1 + 1] - layer[j0 * sx + i1 + 1] - layer[(j1 + 1) * sx + i0] +
         layer[j0 * sx + i0];
}

void ShadowGrid::propagate() {
  build_summed_area_tables();
  if (++stamp_ == 0) {  // the stamps wrapped: every shade is unknown again
    std::fill(shade_stamp_.begin(), shade_stamp_.end(), 0u);
    stamp_ = 1;
  }
  falloff_.resize(p_.depth_voxels + 1);
  for (int q = 0; q <= p_.depth_voxels; ++q) falloff_[q] = std::pow(p_.shade_b, -q);
}

double ShadowGrid::voxel_shade(std::size_t at, int i, int j, int k) const {
  // Computed when first asked: buds and their neighbours are a small part of the grid.
  double& s = shade_[at];
  if (shade_stamp_[at] == stamp_) return s;
  shade_stamp_[at] = stamp_;
  s = pyramid_sum(i, j, k);
  return s;
}

double ShadowGrid::pyramid_sum(int i, int j, int k) const {
  // Palubicki: s(i, j, k) = sum over q of b^-q times the sources of layer k + q within the
  // square of half width q above (i, j).
  if (leaning_) return leaning_pyramid_sum(i, j, k);
  const int q_max = p_.depth_voxels;
  const int q_last = std::min(q_max, n_.z() - 1 - k);
  double sum = 0.0;
  if (i < q_max || j < q_max || i + q_max >= n_.x() || j + q_max >= n_.y()) {
    for (int q = 0; q <= q_last; ++q)
      sum += falloff_[q] * box_sum(k + q, i - q, i + q, j - q, j + q);
    return sum;
  }
  // Every square lies inside its layer (the usual case: reset() leaves q_max + 1 voxels of
  // margin): box_sum without the clipping, the same terms in the same order.
  const std::size_t sx = static_cast<std::size_t>(n_.x()) + 1;
  const std::size_t layer_size = sx * (static_cast<std::size_t>(n_.y()) + 1);
  const double* layer = sat_.data() + static_cast<std::size_t>(k) * layer_size;
  for (int q = 0; q <= q_last; ++q, layer += layer_size) {
    const std::size_t lo_row = static_cast<std::size_t>(j - q) * sx;
    const std::size_t hi_row = static_cast<std::size_t>(j + q + 1) * sx;
    const std::size_t lo_col = static_cast<std::size_t>(i - q);
    const std::size_t hi_col = static_cast<std::size_t>(i + q + 1);
    sum += falloff_[q] * (layer[hi_row + hi_col] - layer[lo_row + hi_col] - layer[hi_row + lo_col] +
                          layer[lo_row + lo_col]);
  }
  return sum;
}

double ShadowGrid::leaning_pyramid_sum(int i, int j, int k) const {
  // The same squares centred q layers up the light direction: (i + shift_x[q], j + shift_y[q]).
  const int q_last = std::min(p_.depth_voxels, n_.z() - 1 - k);
  double sum = 0.0;
  for (int q = 0; q <= q_last; ++q) {
    const int ci = i + shift_x_[q], cj = j + shift_y_[q];
    sum += falloff_[q] * box_sum(k + q, ci - q, ci + q, cj - q, cj + q);
  }
  return sum;
}

namespace {

// Corner c (bits x, y, z) of the eight voxel centres around a point.
Eigen::Vector3i corner_offset(int c) { return {c & 1, (c >> 1) & 1, (c >> 2) & 1}; }

}  // namespace

bool ShadowGrid::locate(const Eigen::Vector3d& p, Corners& k) const {
  const Eigen::Vector3d g = (p - origin_) / p_.voxel_size_m - Eigen::Vector3d::Constant(0.5);
  const Eigen::Vector3d base = g.array().floor();
  if (!base.allFinite() || (base.array().abs() > 1e9).any()) return false;
  k.base = base.cast<int>();
  k.t = g - base;
  const double wx[2] = {1.0 - k.t.x(), k.t.x()}, wy[2] = {1.0 - k.t.y(), k.t.y()},
               wz[2] = {1.0 - k.t.z(), k.t.z()};
  for (int c = 0; c < 8; ++c) k.w[c] = wx[c & 1] * wy[(c >> 1) & 1] * wz[(c >> 2) & 1];
  k.all_inside = (k.base.array() >= 0).all() && (k.base.array() + 1 < n_.array()).all();
  k.at = k.all_inside ? index(k.base.x(), k.base.y(), k.base.z()) : 0;
  return true;
}

void ShadowGrid::add_bud_spread(const Eigen::Vector3d& p, double weight) {
  Corners k;
  if (locate(p, k)) add_bud_spread(k, weight);
}

void ShadowGrid::add_bud_spread(const Corners& k, double weight) {
  for (int c = 0; c < 8; ++c) {
    const double w = k.w[c];
    if (w <= 0.0) continue;
    std::size_t at;
    if (k.all_inside) {
      at = corner_index(k, c);
    } else {
      const Eigen::Vector3i v = k.base + corner_offset(c);
      if (!inside(v)) continue;
      at = index(v.x(), v.y(), v.z());
    }
    source_[at] += p_.shade_a * weight * w;
    touched_.push_back(at);
  }
}

double ShadowGrid::upper_share_in_square(const Corners& k, int c) const {
  // Under a lean a lower corner's square one layer up is centred shift(1) voxels aside and may
  // leave out some of the upper corners.
  double share = 0.0;
  for (int u = 4; u < 8; ++u) {
    const int dx = (u & 1) - (c & 1), dy = ((u >> 1) & 1) - ((c >> 1) & 1);
    if (std::abs(dx - shift_x_[1]) <= 1 && std::abs(dy - shift_y_[1]) <= 1) share += k.w[u];
  }
  return share;
}

// Palubicki's Q / C at each corner without the bud's own shade: its share a w at the corner
// itself, and at a lower corner the upper corners' shares one layer up (every lower corner's
// pyramid takes in all four, at b^-1). Outside the grid nothing shades.
double ShadowGrid::spread_bud_light(const Eigen::Vector3d& p) const {
  Corners k;
  return locate(p, k) ? spread_bud_light(k) : 1.0;
}

double ShadowGrid::spread_bud_light(const Corners& k) const {
  const double upper_share = k.t.z();
  double light = 0.0;
  for (int c = 0; c < 8; ++c) {
    const double w = k.w[c];
    if (w <= 0.0) continue;
    const Eigen::Vector3i v = k.base + corner_offset(c);
    if (!k.all_inside && !inside(v)) {
      light += w;
      continue;
    }
    const std::size_t at = k.all_inside ? corner_index(k, c) : index(v.x(), v.y(), v.z());
    if (obstacle_[at]) continue;
    const bool upper = (c >> 2) != 0;
    const double below = upper ? 0.0 : leaning_ ? upper_share_in_square(k, c) : upper_share;
    const double own = p_.shade_a * (w + below / p_.shade_b);
    const double s = voxel_shade(at, v.x(), v.y(), v.z()) - own;
    light += w * std::min(std::max(p_.full_light - s, 0.0) / p_.full_light, 1.0);
  }
  return light;
}

Eigen::Vector3d ShadowGrid::spread_light_direction(const Eigen::Vector3d& p) const {
  Corners k;
  if (!locate(p, k)) return light_axis();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (int c = 0; c < 8; ++c) {
    const double w = k.w[c];
    if (w <= 0.0) continue;
    const Eigen::Vector3i v = k.base + corner_offset(c);
    d += w * (k.all_inside || inside(v) ? light_direction_at(v) : light_axis());
  }
  return d.normalized();
}

double ShadowGrid::shade(const Eigen::Vector3d& p) const {
  Eigen::Vector3i v;
  return voxel_of(p, v) ? voxel_shade(v.x(), v.y(), v.z()) : 0.0;
}

bool ShadowGrid::obstacle(const Eigen::Vector3d& p) const {
  Eigen::Vector3i v;
  return voxel_of(p, v) && obstacle_[index(v.x(), v.y(), v.z())] != 0;
}

double ShadowGrid::bud_light(const Eigen::Vector3d& p) const {
  Eigen::Vector3i v;
  if (!voxel_of(p, v)) return 1.0;
  const std::size_t at = index(v.x(), v.y(), v.z());
  if (obstacle_[at]) return 0.0;
  // Palubicki: Q = max(C - s + a, 0).
  const double q = std::max(p_.full_light - voxel_shade(v.x(), v.y(), v.z()) + p_.shade_a, 0.0);
  return std::min(q / p_.full_light, 1.0);
}

Eigen::Vector3d ShadowGrid::growth_direction(const Eigen::Vector3d& p) const {
  Eigen::Vector3i v;
  if (!voxel_of(p, v)) return Eigen::Vector3d::UnitZ();
  constexpr double kTie = 1e-9;
  double best = 1e300;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int dk = -1; dk <= 1; ++dk) {
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        const Eigen::Vector3i w = v + Eigen::Vector3i(di, dj, dk);
        if ((di == 0 && dj == 0 && dk == 0) || (w.array() < 0).any() ||
            (w.array() >= n_.array()).any()) {
          continue;
        }
        const std::size_t at = index(w.x(), w.y(), w.z());
        if (obstacle_[at]) continue;
        const double s = voxel_shade(w.x(), w.y(), w.z());
        const Eigen::Vector3d u = Eigen::Vector3d(di, dj, dk).normalized();
        if (s < best - kTie) {
          best = s;
          sum = u;
        } else if (s <= best + kTie) {
          sum += u;
        }
      }
    }
  }
  return sum.norm() > 1e-12 ? Eigen::Vector3d(sum.normalized()) : Eigen::Vector3d::UnitZ();
}

Eigen::Vector3d ShadowGrid::light_direction(const Eigen::Vector3d& p) const {
  Eigen::Vector3i v;
  if (!voxel_of(p, v)) return light_axis();
  return light_direction_at(v);
}

Eigen::Vector3d ShadowGrid::light_direction_at(const Eigen::Vector3i& v) const {
  const double dark = p_.full_light + p_.shade_a;
  const auto shade_at = [&](Eigen::Vector3i w) {
    // Beyond the grid's side nothing is known: the same as the voxel itself.
    for (int a = 0; a < 2; ++a) w[a] = std::clamp(w[a], 0, n_[a] - 1);
    const std::size_t at = index(w.x(), w.y(), w.z());
    return obstacle_[at] ? dark : voxel_shade(at, w.x(), w.y(), w.z());
  };
  // The light comes through the 45-degree cone of the shadow pyramid: from the zenith when both
  // sides are equally shaded, tilted toward the brighter side by up to the cone's half angle when
  // one side is dark (a shade difference of C) and the other open.
  const Eigen::Vector2d away(
      shade_at(v - Eigen::Vector3i::UnitX()) - shade_at(v + Eigen::Vector3i::UnitX()),
      shade_at(v - Eigen::Vector3i::UnitY()) - shade_at(v + Eigen::Vector3i::UnitY()));
  // Under a lean the cone's axis is the light direction (lean_ = 0 at the zenith).
  const double norm = away.norm();
  if (norm <= 1e-12) return light_axis();
  const double tilt = std::min(1.0, norm / p_.full_light);  // tan of the tilt angle
  return Eigen::Vector3d(lean_.x() + tilt * away.x() / norm, lean_.y() + tilt * away.y() / norm,
                         1.0)
      .normalized();
}

}  // namespace fspm::environment
