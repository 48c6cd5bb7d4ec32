#include "scans/circle_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace fspm::scans {

std::optional<Circle> fit_circle_kasa(const std::vector<Eigen::Vector2d>& points) {
  if (points.size() < 3) return std::nullopt;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  // x^2 + y^2 + D x + E y + F = 0 in the least-squares sense (Kasa 1976), about the mean.
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (const Eigen::Vector2d& p : points) {
    const Eigen::Vector2d q = p - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    ata += row * row.transpose();
    atb -= row * q.squaredNorm();
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(ata);
  if (lu.rank() < 3) return std::nullopt;
  const Eigen::Vector3d c = lu.solve(atb);
  const double r2 = 0.25 * (c[0] * c[0] + c[1] * c[1]) - c[2];
  if (!(r2 > 0.0) || !std::isfinite(r2)) return std::nullopt;
  Circle out;
  out.centre = mean - 0.5 * Eigen::Vector2d(c[0], c[1]);
  out.radius_m = std::sqrt(r2);
  double sum = 0.0;
  for (const Eigen::Vector2d& p : points) {
    const double d = (p - out.centre).norm() - out.radius_m;
    sum += d * d;
  }
  out.rms_m = std::sqrt(sum / static_cast<double>(points.size()));
  return out;
}

}  // namespace fspm::scans
