#include "environment/canopy_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "environment/canopy_light.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// An opaque cluster's extinction, capped so that the voxels' sums stay finite (exp(-100 h) is
// dark at any voxel size used).
constexpr double kMaxExtinction = 100.0;

using Cell = CanopySweep::Cell;

float trilinear(const std::vector<float>& v, const Cell& c, std::size_t sy, std::size_t sz) {
  const float* p = v.data() + c.base;
  const float x00 = p[0] + c.fx * (p[1] - p[0]);
  const float x10 = p[sy] + c.fx * (p[sy + 1] - p[sy]);
  const float x01 = p[sz] + c.fx * (p[sz + 1] - p[sz]);
  const float x11 = p[sy + sz] + c.fx * (p[sy + sz + 1] - p[sy + sz]);
  const float y0 = x00 + c.fy * (x10 - x00), y1 = x01 + c.fy * (x11 - x01);
  return y0 + c.fz * (y1 - y0);
}

}  // namespace

namespace {

Sky cos2_sky(int directions, const Eigen::Vector3d& brightest) {
  Sky sky;
  sky.directions = directions;
  sky.brightest =
      brightest.norm() > 0.0 ? Eigen::Vector3d(brightest.normalized()) : Eigen::Vector3d::UnitZ();
  return sky;
}

}  // namespace

CanopySweep::CanopySweep(int directions, const Eigen::Vector3d& brightest, double voxel_m)
    : CanopySweep(cos2_sky(directions, brightest), voxel_m) {}

CanopySweep::CanopySweep(const Sky& sky, double voxel_m) : dirs_(sky.directions), h_(voxel_m) {
  if (!(voxel_m > 0.0)) {
    throw ValueError("canopy sweep: voxel size must be > 0 m, got " + std::to_string(voxel_m));
  }
  weight_ = sky_weights(sky, dirs_);  // Pirk eq. 4.3's cos^2, or a real sky's light
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int i = 0; i < dirs_.size(); ++i) {
    weight_sum_ += weight_[static_cast<std::size_t>(i)];
    m += weight_[static_cast<std::size_t>(i)] * dirs_.direction(i);
  }
  if (m.norm() > 0.0) open_direction_ = m.normalized();
}

// Every cluster adds its extinction to the voxels it fills, in proportion to the share of 2 x 2 x 2
// samples per voxel inside its sphere, scaled so that the grid holds its extinction times volume
// (a cluster smaller than the samples goes whole into the voxel of its centre).
void CanopySweep::bin(std::span<const Sphere> clusters, std::span<const Eigen::Vector3d> points) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const Sphere& c : clusters) {
    lo = lo.cwiseMin(c.center - Eigen::Vector3d::Constant(c.radius_m));
    hi = hi.cwiseMax(c.center + Eigen::Vector3d::Constant(c.radius_m));
  }
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  lo_ = lo;
  const Eigen::Vector3i m = (((hi - lo) / h_).array().ceil().cast<int>() + 1).max(1).matrix();
  n_ = m.array() + 2;
  const std::size_t total = static_cast<std::size_t>(n_.x()) * n_.y() * n_.z();
  kappa_.assign(total, 0.0f);
  a_.assign(total, 0.0f);
  const double voxel3 = h_ * h_ * h_;
  const auto voxel_of = [&](double x, int k) {
    return std::clamp(static_cast<int>(std::lround((x - lo_[k]) / h_)) + 1, 1, m[k]);
  };
  for (const Sphere& c : clusters) {
    const double mu = std::min(cluster_extinction_per_m(c), kMaxExtinction);
    if (!(mu > 0.0)) continue;
    const double r2 = c.radius_m * c.radius_m;
    Eigen::Vector3i a, b;
    for (int k = 0; k < 3; ++k) {
      a[k] = voxel_of(c.center[k] - c.radius_m, k);
      b[k] = voxel_of(c.center[k] + c.radius_m, k);
    }
    // Squared offsets of the two samples per voxel along each axis (the voxel centre +- h / 4).
    for (int k = 0; k < 3; ++k) {
      offset2_[k].clear();
      for (int i = a[k]; i <= b[k]; ++i) {
        for (const double s : {-0.25, 0.25}) {
          const double o = lo_[k] + h_ * (i - 1 + s) - c.center[k];
          offset2_[k].push_back(o * o);
        }
      }
    }
    // Per axis and voxel the nearer and farther of its two samples: a voxel whose farther
    // samples are all inside counts 8 at once, one whose nearer samples are all outside 0.
    for (int k = 0; k < 3; ++k) {
      near2_[k].clear();
      far2_[k].clear();
      for (std::size_t i = 0; i < offset2_[k].size(); i += 2) {
        near2_[k].push_back(std::min(offset2_[k][i], offset2_[k][i + 1]));
        far2_[k].push_back(std::max(offset2_[k][i], offset2_[k][i + 1]));
      }
    }
    inside_.clear();
    int count = 0;
    const std::vector<double>&ox = offset2_[0], &oy = offset2_[1], &oz = offset2_[2];
    for (std::size_t z = 0; z < near2_[2].size(); ++z) {
      for (std::size_t y = 0; y < near2_[1].size(); ++y) {
        const double near_yz = near2_[1][y] + near2_[2][z], far_yz = far2_[1][y] + far2_[2][z];
        for (std::size_t x = 0; x < near2_[0].size(); ++x) {
          int in = 0;
          if (far2_[0][x] + far_yz < r2) {
            in = 8;
          } else if (near2_[0][x] + near_yz < r2) {
            for (int s = 0; s < 8; ++s) {
              in += ox[2 * x + (s & 1)] + oy[2 * y + ((s >> 1) & 1)] + oz[2 * z + (s >> 2)] < r2;
            }
          }
          inside_.push_back(static_cast<std::uint8_t>(in));
          count += in;
        }
      }
    }
    const double amount = mu * 4.0 / 3.0 * std::numbers::pi * r2 * c.radius_m;
    if (count == 0) {
      const std::size_t at =
          index(voxel_of(c.center.x(), 0), voxel_of(c.center.y(), 1), voxel_of(c.center.z(), 2));
      kappa_[at] += static_cast<float>(amount / voxel3);
      continue;
    }
    const double per_sample = amount / (count * voxel3 / 8.0) / 8.0;
    std::size_t k = 0;
    for (int z = a.z(); z <= b.z(); ++z) {
      for (int y = a.y(); y <= b.y(); ++y) {
        for (int x = a.x(); x <= b.x(); ++x, ++k) {
          if (inside_[k] != 0)
            kappa_[index(x, y, z)] += static_cast<float>(per_sample * inside_[k]);
        }
      }
    }
  }
  // Which rows along x (per z, y) and along y (per z, x) hold leaves, for sweep().
  row_leaves_x_.assign(static_cast<std::size_t>(n_.z()) * n_.y(), 0);
  row_leaves_y_.assign(static_cast<std::size_t>(n_.z()) * n_.x(), 0);
  for (int z = 0; z < n_.z(); ++z) {
    for (int y = 0; y < n_.y(); ++y) {
      for (int x = 0; x < n_.x(); ++x) {
        if (kappa_[index(x, y, z)] == 0.0f) continue;
        row_leaves_x_[static_cast<std::size_t>(z) * n_.y() + y] = 1;
        row_leaves_y_[static_cast<std::size_t>(z) * n_.x() + x] = 1;
      }
    }
  }
}

// a_ of every interior voxel for the rays along d (toward the sky): the upstream point lies in the
// neighbouring layer across the axis most aligned with d, at most one voxel sideways.
void CanopySweep::sweep(const Eigen::Vector3d& d) {
  int a = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(d[k]) > std::abs(d[a])) a = k;
  }
  // The inner loop runs along the axis of the smallest stride besides a (x unless a is x).
  const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;
  const std::ptrdiff_t stride[3] = {1, n_.x(), static_cast<std::ptrdiff_t>(n_.x()) * n_.y()};
  const double inv = 1.0 / std::abs(d[a]);
  const int sa = d[a] > 0.0 ? 1 : -1;
  const auto split = [](double u, int& o, float& f) {
    o = static_cast<int>(std::floor(u));
    f = static_cast<float>(u - o);
    if (o >= 1) o = 0, f = 1.0f;  // u == 1 exactly
  };
  int ob, oc;
  float fb, fc;
  split(d[b] * inv, ob, fb);
  split(d[c] * inv, oc, fc);
  const float w00 = (1 - fb) * (1 - fc), w10 = fb * (1 - fc), w01 = (1 - fb) * fc, w11 = fb * fc;
  const auto step = static_cast<float>(h_ * inv);  // path between a voxel and its upstream point
  const std::ptrdiff_t sb = stride[b], sc = stride[c];
  const std::ptrdiff_t up = sa * stride[a] + ob * sb + oc * sc;
  const int ma = n_[a] - 2, mb = n_[b] - 2, mc = n_[c] - 2;
  float* A = a_.data();
  const float* K = kappa_.data();
  // Rows with no leaves and no shade-carrying upstream rows stay zero: they are cleared, not
  // swept (the space around the crown and beside its shadow).
  row_lit_.assign(static_cast<std::size_t>(n_[a]) * n_[c], 0);
  const auto leafy = [&](int ia, int ic) -> bool {
    if (a == 2) return row_leaves_x_[static_cast<std::size_t>(ia) * n_.y() + ic] != 0;
    if (a == 1) return row_leaves_x_[static_cast<std::size_t>(ic) * n_.y() + ia] != 0;
    return row_leaves_y_[static_cast<std::size_t>(ic) * n_.x() + ia] != 0;
  };
  for (int s = 0; s < ma; ++s) {
    const int ia = sa > 0 ? ma - s : 1 + s;
    for (int ic = 1; ic <= mc; ++ic) {
      const std::ptrdiff_t row = ia * stride[a] + ic * sc + sb;
      const std::size_t up_row = static_cast<std::size_t>(ia + sa) * n_[c] + (ic + oc);
      const bool lit = leafy(ia, ic) || row_lit_[up_row] != 0 || row_lit_[up_row + 1] != 0;
      // The upstream layer is another layer: no aliasing within a row.
      float* __restrict out = A + row;
      if (!lit) {
        for (int ib = 0; ib < mb; ++ib) out[ib * sb] = 0.0f;
        continue;
      }
      row_lit_[static_cast<std::size_t>(ia) * n_[c] + ic] = 1;
      const float* __restrict in = A + row + up;
      const float* __restrict k = K + row;
      if (sb == 1) {
        for (int ib = 0; ib < mb; ++ib) {
          out[ib] = w00 * in[ib] + w10 * in[ib + 1] + w01 * in[ib + sc] + w11 * in[ib + 1 + sc] +
                    step * k[ib];
        }
        continue;
      }
      for (int ib = 0; ib < mb; ++ib) {
        const std::ptrdiff_t o = ib * sb;
        out[o] =
            w00 * in[o] + w10 * in[o + sb] + w01 * in[o + sc] + w11 * in[o + sb + sc] + step * k[o];
      }
    }
  }
}

void CanopySweep::prepare(std::span<const Sphere> clusters,
                          std::span<const Eigen::Vector3d> points) {
  bin(clusters, points);
  const std::size_t sy = static_cast<std::size_t>(n_.x());
  const std::size_t sz = sy * static_cast<std::size_t>(n_.y());
  cells_.resize(points.size());
  kappa_at_.resize(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector3d f = (points[k] - lo_) / h_;
    Eigen::Vector3i i;
    for (int j = 0; j < 3; ++j) i[j] = std::clamp(static_cast<int>(std::floor(f[j])), 0, n_[j] - 3);
    cells_[k] = {index(i.x() + 1, i.y() + 1, i.z() + 1), static_cast<float>(f.x() - i.x()),
                 static_cast<float>(f.y() - i.y()), static_cast<float>(f.z() - i.z())};
    kappa_at_[k] = trilinear(kappa_, cells_[k], sy, sz);
  }
}

void CanopySweep::transmit(const Eigen::Vector3d& d, std::span<float> out) {
  sweep(d);
  const std::size_t sy = static_cast<std::size_t>(n_.x());
  const std::size_t sz = sy * static_cast<std::size_t>(n_.y());
  const auto half = static_cast<float>(0.5 * h_ / d.cwiseAbs().maxCoeff());
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const float tau = std::max(0.0f, trilinear(a_, cells_[k], sy, sz) - half * kappa_at_[k]);
    out[k] = std::exp(-tau);
  }
}

void CanopySweep::transmissions(std::span<const Sphere> clusters,
                                std::span<const Eigen::Vector3d> points,
                                std::span<const Eigen::Vector3d> directions, std::span<float> out) {
  if (points.empty()) return;
  prepare(clusters, points);
  const std::size_t np = points.size();
  for (std::size_t i = 0; i < directions.size(); ++i) {
    transmit(directions[i], out.subspan(i * np, np));
  }
}

void CanopySweep::evaluate(std::span<const Sphere> clusters,
                           std::span<const Eigen::Vector3d> points,
                           std::span<const std::span<const float>> visibility,
                           std::span<LightSample> out) {
  const std::size_t np = points.size();
  if (np == 0) return;
  prepare(clusters, points);
  std::vector<double> sum(np, 0.0);
  std::vector<Eigen::Vector3d> moment(np, Eigen::Vector3d::Zero());
  std::vector<float> t(np);
  for (int i = 0; i < dirs_.size(); ++i) {
    const double w = weight_[static_cast<std::size_t>(i)];
    if (w <= 0.0) continue;
    const Eigen::Vector3d& d = dirs_.direction(i);
    transmit(d, t);
    for (std::size_t k = 0; k < np; ++k) {
      double v = w * t[k];
      if (!visibility.empty() && !visibility[k].empty()) {
        v *= visibility[k][static_cast<std::size_t>(i)];
      }
      sum[k] += v;
      moment[k] += v * d;
    }
  }
  for (std::size_t k = 0; k < np; ++k) {
    out[k].light = weight_sum_ > 0.0 ? std::clamp(sum[k] / weight_sum_, 0.0, 1.0) : 0.0;
    out[k].direction =
        moment[k].norm() > 1e-300 ? Eigen::Vector3d(moment[k].normalized()) : open_direction_;
  }
}

}  // namespace fspm::environment
