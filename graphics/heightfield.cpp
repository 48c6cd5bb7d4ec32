#include "graphics/heightfield.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/vertex_normals.hpp"

namespace fspm::graphics {
namespace {

// Sample indices along one direction: 0, stride, 2 stride, ... and the last.
std::vector<int> grid_lines(int count, int stride) {
  std::vector<int> out;
  for (int i = 0; i < count - 1; i += stride) out.push_back(i);
  out.push_back(count - 1);
  return out;
}

// Area-weighted vertex normals from the triangles around each vertex.
void add_normals(TriangleMesh& mesh) {
  mesh.normals = area_weighted_vertex_normals(mesh.positions, mesh.triangles);
}

}  // namespace

Heightfield::Heightfield(FloatImage image, double metres_per_pixel, double height_scale_m,
                         const std::string& file)
    : image_(std::move(image)),
      metres_per_pixel_(metres_per_pixel),
      height_scale_m_(height_scale_m) {
  if (image_.width < 2 || image_.height < 2) {
    throw ValueError("a heightfield needs at least 2 x 2 pixels", file);
  }
  if (!(metres_per_pixel_ > 0.0) || !std::isfinite(metres_per_pixel_)) {
    throw ValueError("metres_per_pixel must be a positive number", file);
  }
  for (float v : image_.values) {
    if (!std::isfinite(v)) throw ValueError("the heightfield has a value that is not finite", file);
  }
}

double Heightfield::height_at(double x_m, double y_m) const {
  // Continuous sample coordinates: u along columns, v along rows from the top.
  const double u = std::clamp(x_m / metres_per_pixel_, 0.0, columns() - 1.0);
  const double v = std::clamp((rows() - 1.0) - y_m / metres_per_pixel_, 0.0, rows() - 1.0);
  const int i = std::min(static_cast<int>(u), columns() - 2);
  const int j = std::min(static_cast<int>(v), rows() - 2);
  const double fu = u - i, fv = v - j;
  const double top = (1.0 - fu) * sample_m(i, j) + fu * sample_m(i + 1, j);
  const double bottom = (1.0 - fu) * sample_m(i, j + 1) + fu * sample_m(i + 1, j + 1);
  return (1.0 - fv) * top + fv * bottom;
}

TriangleMesh heightfield_mesh(const Heightfield& terrain, int stride) {
  if (stride < 1) throw ValueError("the terrain stride must be at least 1");
  const std::vector<int> is = grid_lines(terrain.columns(), stride);
  const std::vector<int> js = grid_lines(terrain.rows(), stride);
  const std::size_t vertices = is.size() * js.size();
  const std::size_t triangles = 2 * (is.size() - 1) * (js.size() - 1);
  check_memory(TriangleMesh::bytes_for(vertices, triangles, 0),
               "the terrain mesh of " + std::to_string(is.size()) + " x " +
                   std::to_string(js.size()) + " vertices (terrain.stride " +
                   std::to_string(stride) + ")");
  TriangleMesh mesh;
  mesh.positions.reserve(vertices);
  mesh.triangles.reserve(triangles);
  const double s = terrain.metres_per_pixel();
  for (int j : js) {
    for (int i : is) {
      mesh.positions.emplace_back(static_cast<float>(i * s),
                                  static_cast<float>((terrain.rows() - 1 - j) * s),
                                  static_cast<float>(terrain.sample_m(i, j)));
    }
  }
  const auto index = [&](std::size_t a, std::size_t b) {
    return static_cast<std::uint32_t>(b * is.size() + a);
  };
  // Rows run from north to south, so (a, b + 1) is south of (a, b): counter-clockwise from above.
  for (std::size_t b = 0; b + 1 < js.size(); ++b) {
    for (std::size_t a = 0; a + 1 < is.size(); ++a) {
      mesh.triangles.push_back({index(a, b), index(a, b + 1), index(a + 1, b + 1)});
      mesh.triangles.push_back({index(a, b), index(a + 1, b + 1), index(a + 1, b)});
    }
  }
  mesh.materials.assign(mesh.triangles.size(), Material::kTerrain);
  add_normals(mesh);
  return mesh;
}

}  // namespace fspm::graphics
