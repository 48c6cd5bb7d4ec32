#include "io/obstacle_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fspm/error.hpp"

namespace fspm::io {
namespace {

using graphics::Material;
using graphics::TriangleMesh;

std::uint32_t add_vertex(TriangleMesh& mesh, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
                         const Eigen::Vector2f& uv) {
  const auto index = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(p.cast<float>());
  mesh.normals.push_back(n.cast<float>());
  mesh.uvs.push_back(uv);
  for (auto& a : mesh.attributes) a.values.push_back(0.0f);
  return index;
}

void add_triangle(TriangleMesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  mesh.triangles.push_back({a, b, c});
  mesh.materials.push_back(Material::kObstacle);
}

// An obstacle's share of the mesh: its first vertex and triangle, and how much light it lets
// through.
struct ObstacleRange {
  std::size_t first_vertex = 0;
  std::size_t first_triangle = 0;
  double translucency = 0.0;
};

// Obstacles that let light through get the translucent material, and every obstacle vertex its
// translucency (the renders draw each obstacle as see-through as it is).
void mark_translucency(TriangleMesh& mesh, const std::vector<ObstacleRange>& ranges) {
  const bool any = std::any_of(ranges.begin(), ranges.end(),
                               [](const ObstacleRange& r) { return r.translucency > 0.0; });
  if (!any) return;
  std::vector<float>& gamma = mesh.add_attribute("translucency");
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    if (ranges[i].translucency <= 0.0) continue;
    const std::size_t vertex_end =
        i + 1 < ranges.size() ? ranges[i + 1].first_vertex : mesh.vertex_count();
    const std::size_t triangle_end =
        i + 1 < ranges.size() ? ranges[i + 1].first_triangle : mesh.triangle_count();
    std::fill(gamma.begin() + static_cast<std::ptrdiff_t>(ranges[i].first_vertex),
              gamma.begin() + static_cast<std::ptrdiff_t>(vertex_end),
              static_cast<float>(ranges[i].translucency));
    for (std::size_t t = ranges[i].first_triangle; t < triangle_end; ++t) {
      mesh.materials[t] = Material::kTranslucentObstacle;
    }
  }
}

}  // namespace

void append_box_mesh(const environment::Box& box, TriangleMesh& mesh) {
  const Eigen::Matrix3d& r = box.rotation;
  const Eigen::Vector3d& h = box.half_extent;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    for (double s : {1.0, -1.0}) {
      const Eigen::Vector3d normal = s * r.col(i);
      const Eigen::Vector3d face = box.center + s * h[i] * r.col(i);
      // (u, v) spans the face with u x v along the outward normal for a proper rotation.
      Eigen::Vector3d u = h[j] * r.col(j);
      Eigen::Vector3d v = h[k] * r.col(k);
      if (s < 0) std::swap(u, v);
      if (r.determinant() < 0) std::swap(u, v);  // a reflection flips the winding
      const std::uint32_t a = add_vertex(mesh, face - u - v, normal, {0, 0});
      const std::uint32_t b = add_vertex(mesh, face + u - v, normal, {1, 0});
      const std::uint32_t c = add_vertex(mesh, face + u + v, normal, {1, 1});
      const std::uint32_t d = add_vertex(mesh, face - u + v, normal, {0, 1});
      add_triangle(mesh, a, b, c);
      add_triangle(mesh, a, c, d);
    }
  }
}

void append_sphere_mesh(const Eigen::Vector3d& center, double radius_m, int segments,
                        TriangleMesh& mesh) {
  if (segments < 3) throw ValueError("a sphere needs at least 3 segments");
  const int meridians = segments;
  const int parallels = std::max(2, segments / 2);
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (int p = 0; p <= parallels; ++p) {
    const double theta = std::numbers::pi * p / parallels;  // from the north pole
    for (int m = 0; m <= meridians; ++m) {                  // the seam is duplicated for the uvs
      const double phi = 2.0 * std::numbers::pi * m / meridians;
      const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      add_vertex(mesh, center + radius_m * n, n,
                 {static_cast<float>(m) / meridians, 1.0f - static_cast<float>(p) / parallels});
    }
  }
  const auto at = [&](int p, int m) {
    return first + static_cast<std::uint32_t>(p * (meridians + 1) + m);
  };
  for (int p = 0; p < parallels; ++p) {
    for (int m = 0; m < meridians; ++m) {
      // Counter-clockwise seen from outside; the pole rows have one triangle per segment.
      if (p > 0) add_triangle(mesh, at(p, m), at(p + 1, m), at(p, m + 1));
      if (p + 1 < parallels) add_triangle(mesh, at(p, m + 1), at(p + 1, m), at(p + 1, m + 1));
    }
  }
}

void append_triangle_mesh(const environment::TriangleMesh& surface, TriangleMesh& mesh) {
  const std::size_t n = surface.vertices.size();
  std::vector<Eigen::Vector3d> normals(n, Eigen::Vector3d::Zero());
  for (const Eigen::Vector3i& t : surface.triangles) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] < 0 || static_cast<std::size_t>(t[k]) >= n) {
        throw ValueError("obstacle mesh: vertex index " + std::to_string(t[k]) +
                         " out of range (expected below " + std::to_string(n) + ")");
      }
    }
    const Eigen::Vector3d& a = surface.vertices[t[0]];
    const Eigen::Vector3d area = (surface.vertices[t[1]] - a).cross(surface.vertices[t[2]] - a);
    for (int k = 0; k < 3; ++k) normals[t[k]] += area;
  }
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double length = normals[i].norm();
    const Eigen::Vector3d normal =
        length > 0 ? Eigen::Vector3d(normals[i] / length) : Eigen::Vector3d::UnitZ();
    add_vertex(mesh, surface.vertices[i], normal, {0, 0});
  }
  for (const Eigen::Vector3i& t : surface.triangles) {
    add_triangle(mesh, first + static_cast<std::uint32_t>(t[0]),
                 first + static_cast<std::uint32_t>(t[1]),
                 first + static_cast<std::uint32_t>(t[2]));
  }
}

TriangleMesh mesh_obstacles(const environment::Scene& scene, int sphere_segments) {
  TriangleMesh mesh;
  std::vector<ObstacleRange> ranges;
  const auto start = [&](double translucency) {
    ranges.push_back({mesh.vertex_count(), mesh.triangle_count(), translucency});
  };
  for (const auto& box : scene.boxes) {
    start(box.translucency);
    append_box_mesh(box, mesh);
  }
  for (const auto& sphere : scene.spheres) {
    start(sphere.translucency);
    append_sphere_mesh(sphere.center, sphere.radius_m, sphere_segments, mesh);
  }
  for (const auto& surface : scene.meshes) {
    start(surface.translucency);
    append_triangle_mesh(surface, mesh);
  }
  mark_translucency(mesh, ranges);
  return mesh;
}

}  // namespace fspm::io
