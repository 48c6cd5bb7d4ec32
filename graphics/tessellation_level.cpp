// Reynolds et al. 2011, expression 2.
#include "graphics/tessellation_level.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <utility>

#include "fspm/error.hpp"

namespace fspm::graphics {

void TessellationLimits::validate() const {
  const std::pair<const char*, double> fields[] = {{"max_distance_m", max_distance_m},
                                                   {"max_face_area_m2", max_face_area_m2},
                                                   {"max_level", max_level}};
  for (const auto& [name, x] : fields) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      throw ValueError(std::string("tessellation limits: ") + name +
                       " must be positive and finite");
    }
  }
}

double tessellation_level(double d, double area, const TessellationLimits& l) {
  l.validate();
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

TriangleMesh without_highest_bark_orders(const TriangleMesh& mesh, int dropped) {
  if (dropped < 0) throw ValueError("the branch orders to drop must be >= 0");
  if (dropped == 0 || !mesh.has_attribute("order")) return mesh;
  const std::span<const float> order = mesh.attribute("order");
  const auto face_order = [&](std::size_t t) {
    const auto& tri = mesh.triangles[t];
    return std::max({order[tri[0]], order[tri[1]], order[tri[2]]});
  };
  float highest = 0.0f;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] == Material::kBark) highest = std::max(highest, face_order(t));
  }
  const float kept = std::max(0.0f, highest - static_cast<float>(dropped));
  TriangleMesh out = mesh;
  out.triangles.clear();
  out.materials.clear();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] == Material::kBark && face_order(t) > kept) continue;
    out.triangles.push_back(mesh.triangles[t]);
    out.materials.push_back(mesh.materials[t]);
  }
  return out;
}

}  // namespace fspm::graphics
