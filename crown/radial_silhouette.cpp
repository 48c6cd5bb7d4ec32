#include "crown/radial_silhouette.hpp"

#include <cmath>

#include "fspm/error.hpp"

namespace fspm::crown {

RadialSilhouette::RadialSilhouette(const Mask& mask, int angles) {
  if (angles < 4) throw ValueError("the radial silhouette needs at least 4 angles");
  double sx = 0.0, sy = 0.0, n = 0.0;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y)) sx += x, sy += y, n += 1.0;
    }
  }
  if (n == 0.0) throw ValueError("the crown mask has no crown pixel");
  centre_ = {sx / n, sy / n};
  const double reach = std::hypot(mask.width, mask.height);
  radius_.resize(static_cast<std::size_t>(angles));
  for (int k = 0; k < angles; ++k) {
    const double phi = 2.0 * M_PI * k / angles;
    const Eigen::Vector2d step(std::cos(phi), -std::sin(phi));  // rows run down
    double last = 0.0;
    for (double t = 0.0; t <= reach; t += 0.25) {
      const Eigen::Vector2d p = centre_ + t * step;
      if (mask.at(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())))) {
        last = t;
      }
    }
    radius_[static_cast<std::size_t>(k)] = last;
  }
}

double RadialSilhouette::radius_px(double phi) const {
  const double n = static_cast<double>(radius_.size());
  double u = phi / (2.0 * M_PI) * n;
  u -= n * std::floor(u / n);  // into [0, n)
  const auto i = static_cast<std::size_t>(u) % radius_.size();
  const std::size_t j = (i + 1) % radius_.size();
  const double w = u - std::floor(u);
  return (1.0 - w) * radius_[i] + w * radius_[j];
}

double RadialSilhouette::radius_px(const Eigen::Vector3d& d) const {
  const double alpha = std::atan2(d.z(), std::hypot(d.x(), d.y()));
  const double theta = std::atan2(d.y(), d.x());
  const double s = std::abs(theta) / M_PI;
  return (1.0 - s) * radius_px(alpha) + s * radius_px(M_PI - alpha);
}

}  // namespace fspm::crown
