#include "environment/canopy_summary.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "environment/canopy_light.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

CanopySummary summarize_canopy(std::span<const Sphere> clusters, const Eigen::Vector3d& sun,
                               double pixel_m) {
  if (!(pixel_m > 0.0))
    throw ValueError("pixel size must be > 0 m, got " + std::to_string(pixel_m));
  CanopySummary out;
  out.clusters = clusters.size();
  if (clusters.empty()) return out;
  const Eigen::Vector3d d = sun.normalized();
  const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  double far = -1e300;  // the start of the lines, beyond every cluster away from the sun
  for (const Sphere& c : clusters) {
    out.leaf_area_m2 += cluster_leaf_area_m2(c);
    const Eigen::Vector2d q(c.center.dot(e1), c.center.dot(e2));
    lo = lo.cwiseMin(q - Eigen::Vector2d::Constant(c.radius_m));
    hi = hi.cwiseMax(q + Eigen::Vector2d::Constant(c.radius_m));
    far = std::max(far, -c.center.dot(d) + c.radius_m);
  }
  // Pixel centres on the plane, each the start of a line toward the sun through the crown.
  const int nu = static_cast<int>(std::ceil((hi.x() - lo.x()) / pixel_m));
  const int nv = static_cast<int>(std::ceil((hi.y() - lo.y()) / pixel_m));
  std::vector<Eigen::Vector3d> starts;
  starts.reserve(static_cast<std::size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = lo.x() + (i + 0.5) * pixel_m, v = lo.y() + (j + 0.5) * pixel_m;
      starts.push_back(u * e1 + v * e2 - (far + 1.0) * d);
    }
  }
  const CanopyLight light(Scene{}, clusters);
  std::vector<double> t(starts.size());
  light.transmission_along(starts, d, {}, t);
  for (const double v : t) out.silhouette_area_m2 += (1.0 - v) * pixel_m * pixel_m;
  out.sunlit_leaf_area_m2 =
      std::min(out.silhouette_area_m2 / kSphericalLeafProjection, out.leaf_area_m2);
  out.shaded_leaf_area_m2 = out.leaf_area_m2 - out.sunlit_leaf_area_m2;
  out.star = out.leaf_area_m2 > 0.0 ? out.silhouette_area_m2 / out.leaf_area_m2 : 0.0;
  return out;
}

}  // namespace fspm::environment
