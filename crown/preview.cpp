#include "crown/preview.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fspm::crown {
namespace {

struct Projected {
  Eigen::Vector2d xy;  // pixel coordinates
  double depth;        // distance from the camera plane
};

Projected project(const Eigen::Vector3f& p, PreviewView view, int width, int height, double s,
                  double ground) {
  if (view == PreviewView::kTop)
    return {{0.5 * width + p.x() / s, 0.5 * height - p.y() / s}, -p.z()};
  const double right = view == PreviewView::kFront ? p.x() : p.y();
  const double depth = view == PreviewView::kFront ? p.y() : -p.x();
  return {{0.5 * width + right / s, ground + 1.0 - p.z() / s}, depth};
}

double edge(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
}

}  // namespace

Raster preview(const CrownMesh& mesh, PreviewView view, int width, int height,
               double metres_per_pixel, double ground_row) {
  Raster out(width, height, 3, 1.0f);
  std::vector<double> zbuf(static_cast<std::size_t>(width) * height,
                           std::numeric_limits<double>::max());
  const Eigen::Vector3f toward_camera = view == PreviewView::kFront  ? Eigen::Vector3f(0, -1, 0)
                                        : view == PreviewView::kSide ? Eigen::Vector3f(1, 0, 0)
                                                                     : Eigen::Vector3f(0, 0, 1);
  // Light from above, in front and from the upper left, as a sun would light a photograph: a
  // light from the camera darkens every outline, so that a lobe standing in front of the crown
  // reads as the rim of a hole.
  const Eigen::Vector3f right =
      view == PreviewView::kSide ? Eigen::Vector3f(0, 1, 0) : Eigen::Vector3f(1, 0, 0);
  const Eigen::Vector3f up =
      view == PreviewView::kTop ? Eigen::Vector3f(0, 1, 0) : Eigen::Vector3f(0, 0, 1);
  const Eigen::Vector3f light = (0.6f * toward_camera + 0.8f * up - 0.5f * right).normalized();
  const std::vector<Eigen::Vector3f> normals = vertex_normals(mesh);
  // Depth cue: the farthest surface a third darker than the nearest, so that what stands in front
  // (a lobe seen from the side) reads as nearer, not as the rim of a hole.
  double near = std::numeric_limits<double>::max(), far = -near;
  for (const auto& p : mesh.positions) {
    const double d = project(p, view, width, height, metres_per_pixel, ground_row).depth;
    near = std::min(near, d), far = std::max(far, d);
  }
  const double depth_range = std::max(1e-9, far - near);
  for (const auto& tri : mesh.triangles) {
    Projected q[3];
    for (int k = 0; k < 3; ++k) {
      q[k] = project(mesh.positions[tri[k]], view, width, height, metres_per_pixel, ground_row);
    }
    const double area = edge(q[0].xy, q[1].xy, q[2].xy);
    if (area == 0.0) continue;
    const int x0 = std::max(
        0, static_cast<int>(std::floor(std::min({q[0].xy.x(), q[1].xy.x(), q[2].xy.x()}))));
    const int x1 = std::min(
        width - 1, static_cast<int>(std::ceil(std::max({q[0].xy.x(), q[1].xy.x(), q[2].xy.x()}))));
    const int y0 = std::max(
        0, static_cast<int>(std::floor(std::min({q[0].xy.y(), q[1].xy.y(), q[2].xy.y()}))));
    const int y1 = std::min(
        height - 1, static_cast<int>(std::ceil(std::max({q[0].xy.y(), q[1].xy.y(), q[2].xy.y()}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2d p(x + 0.5, y + 0.5);
        const double w0 = edge(q[1].xy, q[2].xy, p) / area, w1 = edge(q[2].xy, q[0].xy, p) / area;
        const double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        const double depth = w0 * q[0].depth + w1 * q[1].depth + w2 * q[2].depth;
        double& z = zbuf[static_cast<std::size_t>(y) * width + x];
        if (depth >= z) continue;
        z = depth;
        const Eigen::Vector3f n =
            (w0 * normals[tri[0]] + w1 * normals[tri[1]] + w2 * normals[tri[2]]).normalized();
        const Eigen::Vector3f c =
            w0 * mesh.colors[tri[0]] + w1 * mesh.colors[tri[1]] + w2 * mesh.colors[tri[2]];
        const auto cue = static_cast<float>(1.0 - 0.35 * (depth - near) / depth_range);
        const float shade = cue * (0.45f + 0.75f * std::max(0.0f, n.dot(light)));
        for (int k = 0; k < 3; ++k) out.at(x, y, k) = std::min(1.0f, shade * c[k]);
      }
    }
  }
  return out;
}

}  // namespace fspm::crown
