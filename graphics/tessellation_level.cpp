// Reynolds et al. 2011, expression 2.
#include "graphics/tessellation_level.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"

namespace fspm::graphics {

void validate(const TessellationLimits& l) {
  for (double x : {l.max_distance_m, l.max_face_area_m2, l.max_level}) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      throw ValueError("tessellation limits (distance, face area, level) must be positive");
    }
  }
}

double tessellation_level(double d, double area, const TessellationLimits& l) {
  validate(l);
  if (!(d >= 0.0) || !(area >= 0.0)) {
    throw ValueError("face distance and area must be >= 0");
  }
  const double near = std::clamp(1.0 - d / l.max_distance_m, 0.0, 1.0);
  const double size = std::clamp(area / l.max_face_area_m2, 0.0, 1.0);
  return near * size * l.max_level;
}

std::vector<double> face_tessellation_levels(const TriangleMesh& mesh,
                                             const Eigen::Vector3f& viewer_m,
                                             TessellationLimits limits) {
  std::vector<double> areas(mesh.triangle_count());
  double largest = 0.0;
  for (std::size_t t = 0; t < areas.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3f a = mesh.positions[tri[0]], b = mesh.positions[tri[1]],
                          c = mesh.positions[tri[2]];
    areas[t] = 0.5 * static_cast<double>((b - a).cross(c - a).norm());
    largest = std::max(largest, areas[t]);
  }
  if (limits.max_face_area_m2 == 0.0) limits.max_face_area_m2 = largest > 0.0 ? largest : 1.0;
  std::vector<double> levels(areas.size());
  for (std::size_t t = 0; t < areas.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3f centroid =
        (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0f;
    levels[t] = tessellation_level((centroid - viewer_m).norm(), areas[t], limits);
  }
  return levels;
}

}  // namespace fspm::graphics
