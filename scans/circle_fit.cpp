#include "scans/circle_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fspm::scans {
namespace {

// x^2 + y^2 + D x + E y + F = 0 in the weighted least-squares sense (Kasa 1976), about the
// weighted mean; no rms.
std::optional<Circle> weighted_kasa(const std::vector<Eigen::Vector2d>& points,
                                    const std::vector<double>& weight) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double total = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) mean += weight[i] * points[i], total += weight[i];
  if (!(total > 0.0)) return std::nullopt;
  mean /= total;
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  std::size_t used = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (weight[i] <= 0.0) continue;
    ++used;
    const Eigen::Vector2d q = points[i] - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    ata += weight[i] * row * row.transpose();
    atb -= weight[i] * row * q.squaredNorm();
  }
  if (used < 3) return std::nullopt;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(ata);
  if (lu.rank() < 3) return std::nullopt;
  const Eigen::Vector3d c = lu.solve(atb);
  const double r2 = 0.25 * (c[0] * c[0] + c[1] * c[1]) - c[2];
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  Circle out;
  out.centre = mean - 0.5 * Eigen::Vector2d(c[0], c[1]);
  out.radius_m = std::sqrt(r2);
  return out;
}

std::vector<double> residuals(const std::vector<Eigen::Vector2d>& points, const Circle& c) {
  std::vector<double> r(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) r[i] = (points[i] - c.centre).norm() - c.radius_m;
  return r;
}

double median_abs(const std::vector<double>& values) {
  std::vector<double> a(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) a[i] = std::abs(values[i]);
  const auto mid = a.begin() + static_cast<std::ptrdiff_t>(a.size() / 2);
  std::nth_element(a.begin(), mid, a.end());
  return *mid;
}

}  // namespace

std::optional<Circle> fit_circle_kasa(const std::vector<Eigen::Vector2d>& points) {
  if (points.size() < 3) return std::nullopt;
  std::optional<Circle> out = weighted_kasa(points, std::vector<double>(points.size(), 1.0));
  if (!out) return out;
  double sum = 0.0;
  for (double d : residuals(points, *out)) sum += d * d;
  out->rms_m = std::sqrt(sum / static_cast<double>(points.size()));
  return out;
}

std::optional<RobustCircle> fit_circle_robust(const std::vector<Eigen::Vector2d>& points,
                                              const RobustCircleOptions& o,
                                              const std::optional<Circle>& start) {
  if (points.size() < 3) return std::nullopt;
  std::vector<double> w(points.size(), 1.0);
  std::optional<Circle> c = start ? start : weighted_kasa(points, w);
  if (!c) return std::nullopt;
  std::vector<double> r = residuals(points, *c);
  for (int it = 0; it < o.iterations; ++it) {
    // 1.4826 times the median |residual| estimates the standard deviation of Gaussian
    // residuals whatever the outliers (up to half the points).
    const double scale = std::max(1.4826 * median_abs(r), o.min_scale_m);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double u = r[i] / (o.tukey_c * scale);
      w[i] = std::abs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
    }
    const std::optional<Circle> next = weighted_kasa(points, w);
    if (!next) break;
    const double moved = (next->centre - c->centre).norm() + std::abs(next->radius_m - c->radius_m);
    c = next;
    r = residuals(points, *c);
    if (moved < 1e-6) break;
  }
  RobustCircle out;
  out.circle = *c;
  out.median_residual_m = median_abs(r);
  const double band = o.inlier_sigmas * std::max(1.4826 * out.median_residual_m, o.min_scale_m);
  out.inlier.assign(points.size(), 0);
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (std::abs(r[i]) > band) continue;
    out.inlier[i] = 1;
    ++out.inliers;
    sum += r[i] * r[i];
  }
  out.circle.rms_m = out.inliers ? std::sqrt(sum / static_cast<double>(out.inliers)) : 0.0;
  return out;
}

namespace {

// Whether each of `sectors` equal angular sectors about `centre` holds a point marked in `use`.
std::vector<char> sector_hits(const std::vector<Eigen::Vector2d>& points,
                              const std::vector<char>& use, const Eigen::Vector2d& centre,
                              int sectors) {
  std::vector<char> hit(static_cast<std::size_t>(sectors), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!use.empty() && !use[i]) continue;
    const Eigen::Vector2d d = points[i] - centre;
    const double a = std::atan2(d.y(), d.x()) + std::numbers::pi;  // [0, 2 pi]
    const auto s = static_cast<int>(a / (2.0 * std::numbers::pi) * sectors);
    hit[static_cast<std::size_t>(std::clamp(s, 0, sectors - 1))] = 1;
  }
  return hit;
}

}  // namespace

int angular_sectors(const std::vector<Eigen::Vector2d>& points, const std::vector<char>& use,
                    const Eigen::Vector2d& centre, int sectors) {
  const std::vector<char> hit = sector_hits(points, use, centre, sectors);
  return static_cast<int>(std::count(hit.begin(), hit.end(), 1));
}

int longest_arc_sectors(const std::vector<Eigen::Vector2d>& points, const std::vector<char>& use,
                        const Eigen::Vector2d& centre, int sectors) {
  const std::vector<char> hit = sector_hits(points, use, centre, sectors);
  int best = 0, run = 0;
  for (int k = 0; k < 2 * sectors; ++k) {  // twice around: runs that wrap
    run = hit[static_cast<std::size_t>(k % sectors)] ? run + 1 : 0;
    best = std::max(best, std::min(run, sectors));
  }
  return best;
}

}  // namespace fspm::scans
