#include "crown/side_view.hpp"

#include <algorithm>
#include <cmath>

namespace fspm::crown {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

// Sets the mask pixels whose centres lie in triangle abc (pixel coordinates), either winding.
void fill_triangle(Mask& mask, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                   const Eigen::Vector2d& c) {
  const double area = cross(a, b, c);
  if (area == 0.0) return;
  const int x0 = std::max(0, static_cast<int>(std::floor(std::min({a.x(), b.x(), c.x()}))));
  const int x1 =
      std::min(mask.width - 1, static_cast<int>(std::ceil(std::max({a.x(), b.x(), c.x()}))));
  const int y0 = std::max(0, static_cast<int>(std::floor(std::min({a.y(), b.y(), c.y()}))));
  const int y1 =
      std::min(mask.height - 1, static_cast<int>(std::ceil(std::max({a.y(), b.y(), c.y()}))));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      const double s = area > 0.0 ? 1.0 : -1.0;
      if (s * cross(a, b, p) >= 0.0 && s * cross(b, c, p) >= 0.0 && s * cross(c, a, p) >= 0.0) {
        mask.set(x, y, true);
      }
    }
  }
}

double mean_column(const Mask& m) {
  double sum = 0.0, n = 0.0;
  for (int y = 0; y < m.height; ++y) {
    for (int x = 0; x < m.width; ++x) {
      if (m.at(x, y)) sum += x, n += 1.0;
    }
  }
  return n > 0.0 ? sum / n : 0.0;
}

}  // namespace

Mask side_silhouette(const CrownMesh& mesh, int width, int height, double metres_per_pixel,
                     double ground_row) {
  Mask mask(width, height);
  auto project = [&](std::uint32_t v) {
    const Eigen::Vector3f& p = mesh.positions[v];
    return Eigen::Vector2d(0.5 * width + p.y() / metres_per_pixel,
                           ground_row + 1.0 - p.z() / metres_per_pixel);
  };
  for (std::size_t t = 0; t < mesh.crown_triangles; ++t) {
    const auto& tri = mesh.triangles[t];
    fill_triangle(mask, project(tri[0]), project(tri[1]), project(tri[2]));
  }
  return mask;
}

double intersection_over_union(const Mask& a, const Mask& b) {
  const int shift = static_cast<int>(std::lround(mean_column(a) - mean_column(b)));
  std::size_t both = 0, either = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const bool in_a = a.at(x, y), in_b = b.at(x - shift, y);
      both += in_a && in_b;
      either += in_a || in_b;
    }
  }
  return either > 0 ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
}

}  // namespace fspm::crown
