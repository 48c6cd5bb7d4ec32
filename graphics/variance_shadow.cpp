#include "graphics/variance_shadow.hpp"

#include <algorithm>

namespace fspm::graphics {

double chebyshev_upper_bound(double m1, double m2, double t, double min_variance) {
  if (t <= m1) return 1.0;  // one-sided: only t > mu is bounded
  const double variance = std::max(m2 - m1 * m1, min_variance);  // Pirk eq. 6.11
  const double d = t - m1;
  return variance / (variance + d * d);  // Pirk eq. 6.12, read (t - mu)^2
}

double variance_shadow_light(double m1, double m2, double t, double min_variance, double bleed) {
  const double p = chebyshev_upper_bound(m1, m2, t, min_variance);
  return std::clamp((p - bleed) / (1.0 - bleed), 0.0, 1.0);
}

}  // namespace fspm::graphics
