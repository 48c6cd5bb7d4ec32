#include "scans/alpha_hull.hpp"

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

namespace fspm::scans {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Alpha_shape_vertex_base_3<Kernel>;
using Cb = CGAL::Alpha_shape_cell_base_3<Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds, CGAL::Fast_location>;
using AlphaShape = CGAL::Alpha_shape_3<Delaunay>;

Eigen::Vector3d to_eigen(const Kernel::Point_3& p) { return {p.x(), p.y(), p.z()}; }

// Boundary facets of the shape, oriented away from its interior cell.
void collect_facets(const AlphaShape& shape, AlphaHull& hull) {
  std::vector<AlphaShape::Facet> facets;
  shape.get_alpha_shape_facets(std::back_inserter(facets), AlphaShape::REGULAR);
  std::unordered_map<const void*, std::uint32_t> index;
  auto id = [&](AlphaShape::Vertex_handle v) {
    auto [it, added] = index.try_emplace(&*v, static_cast<std::uint32_t>(hull.vertices.size()));
    if (added) hull.vertices.push_back(to_eigen(v->point()));
    return it->second;
  };
  for (AlphaShape::Facet f : facets) {
    if (shape.classify(f.first) != AlphaShape::INTERIOR) f = shape.mirror_facet(f);
    const int i = f.second;
    std::array<std::uint32_t, 3> tri{id(f.first->vertex((i + 1) & 3)),
                                     id(f.first->vertex((i + 2) & 3)),
                                     id(f.first->vertex((i + 3) & 3))};
    const Eigen::Vector3d a = hull.vertices[tri[0]];
    const Eigen::Vector3d n = (hull.vertices[tri[1]] - a).cross(hull.vertices[tri[2]] - a);
    if (n.dot(a - to_eigen(f.first->vertex(i)->point())) < 0.0) std::swap(tri[1], tri[2]);
    hull.triangles.push_back(tri);
  }
}

// CGAL's triangulation stores its cells in an order that differs from run to run (its spatial
// sort draws from a shared random generator), so the facets come in another order each time.
// Vertices sorted by their coordinates, triangles rotated to start at their smallest index and
// sorted, make one hull one list, and the .clusters file and its decoding the same every run.
void canonical_order(AlphaHull& hull) {
  std::vector<std::uint32_t> order(hull.vertices.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  const auto less = [&](std::uint32_t a, std::uint32_t b) {
    const Eigen::Vector3d& p = hull.vertices[a];
    const Eigen::Vector3d& q = hull.vertices[b];
    return std::tie(p.x(), p.y(), p.z()) < std::tie(q.x(), q.y(), q.z());
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::uint32_t> rank(order.size());
  std::vector<Eigen::Vector3d> vertices(order.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = k;
    vertices[k] = hull.vertices[order[k]];
  }
  hull.vertices = std::move(vertices);
  for (std::array<std::uint32_t, 3>& t : hull.triangles) {
    for (std::uint32_t& i : t) i = rank[i];
    // Rotating keeps the orientation.
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  }
  std::sort(hull.triangles.begin(), hull.triangles.end());
}

}  // namespace

std::vector<Eigen::Vector3d> thin_to_grid(const std::vector<Eigen::Vector3d>& points,
                                          int max_cells) {
  if (points.empty()) return {};
  Eigen::Vector3d lo = points[0], hi = points[0];
  for (const Eigen::Vector3d& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double cell = std::max((hi - lo).maxCoeff() / std::max(max_cells, 1), 1e-9);
  std::map<std::array<std::int64_t, 3>, std::pair<Eigen::Vector3d, int>> cells;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3d q = (p - lo) / cell;
    // try_emplace with a zero sum: a default Eigen vector would be uninitialized.
    auto& c = cells
                  .try_emplace({static_cast<std::int64_t>(q.x()), static_cast<std::int64_t>(q.y()),
                                static_cast<std::int64_t>(q.z())},
                               Eigen::Vector3d::Zero(), 0)
                  .first->second;
    c.first += p;
    ++c.second;
  }
  std::vector<Eigen::Vector3d> out;
  for (auto& [key, c] : cells) out.push_back(c.first / c.second);
  return out;
}

AlphaHull alpha_hull(const std::vector<Eigen::Vector3d>& points, const AlphaHullOptions& options) {
  AlphaHull hull;
  const std::vector<Eigen::Vector3d> thin = thin_to_grid(points, options.max_cells);
  std::vector<Kernel::Point_3> pts;
  for (const Eigen::Vector3d& p : thin) pts.emplace_back(p.x(), p.y(), p.z());
  if (pts.size() >= 4) {
    AlphaShape shape(pts.begin(), pts.end(), 0, AlphaShape::REGULARIZED);
    if (shape.dimension() == 3) {
      const auto optimal = shape.find_optimal_alpha(1);
      if (optimal != shape.alpha_end()) {
        hull.alpha = options.alpha_factor * *optimal;
        shape.set_alpha(hull.alpha);
        collect_facets(shape, hull);
        canonical_order(hull);
        if (!hull.triangles.empty()) return hull;
      }
    }
  }
  hull = AlphaHull{};
  hull.vertices = thin;
  return hull;
}

}  // namespace fspm::scans
