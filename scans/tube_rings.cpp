#include "scans/tube_rings.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <set>

namespace fspm::scans {
namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;
using Neighbours = std::vector<std::set<std::uint32_t>>;

std::uint32_t find_root(std::vector<std::uint32_t>& root, std::uint32_t i) {
  while (root[i] != i) i = root[i] = root[root[i]];
  return i;
}

// Edges (a < b) with the number of faces that use each.
std::map<Edge, int> edge_uses(const std::vector<std::vector<std::uint32_t>>& faces) {
  std::map<Edge, int> uses;
  for (const auto& f : faces) {
    for (std::size_t k = 0; k < f.size(); ++k) ++uses[std::minmax(f[k], f[(k + 1) % f.size()])];
  }
  return uses;
}

Neighbours neighbours_of(const std::map<Edge, int>& uses, std::size_t points) {
  Neighbours n(points);
  for (const auto& [e, count] : uses) n[e.first].insert(e.second), n[e.second].insert(e.first);
  return n;
}

// The vertices of one boundary loop (the one through the lowest-numbered boundary vertex), or
// none when every edge is shared by two faces.
std::vector<std::uint32_t> one_boundary_loop(const std::map<Edge, int>& uses, std::size_t points) {
  Neighbours boundary(points);
  for (const auto& [e, count] : uses) {
    if (count == 1) boundary[e.first].insert(e.second), boundary[e.second].insert(e.first);
  }
  std::vector<std::uint32_t> loop;
  std::vector<bool> seen(points, false);
  for (std::uint32_t v = 0; v < points && loop.empty(); ++v) {
    if (boundary[v].empty()) continue;
    std::vector<std::uint32_t> stack{v};
    seen[v] = true;
    while (!stack.empty()) {
      const std::uint32_t u = stack.back();
      stack.pop_back();
      loop.push_back(u);
      for (std::uint32_t w : boundary[u]) {
        if (!seen[w]) seen[w] = true, stack.push_back(w);
      }
    }
  }
  return loop;
}

// For a closed tube: the vertices at its lowest end along the principal axis of its vertices
// (within a thousandth of its extent, so a flat cap's centre comes with its rim).
std::vector<std::uint32_t> lowest_end(const std::vector<Eigen::Vector3d>& p) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : p) mean += q;
  mean /= static_cast<double>(p.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& q : p) cov += (q - mean) * (q - mean).transpose();
  const Eigen::Vector3d axis =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(2);
  std::vector<double> s(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) s[i] = (p[i] - mean).dot(axis);
  const auto [lo, hi] = std::minmax_element(s.begin(), s.end());
  const double limit = *lo + 1e-3 * (*hi - *lo);
  std::vector<std::uint32_t> out;
  for (std::uint32_t i = 0; i < p.size(); ++i) {
    if (s[i] <= limit) out.push_back(i);
  }
  return out;
}

// Breadth-first rings from `start`: each ring the not yet reached neighbours of the one before.
std::vector<std::vector<std::uint32_t>> rings_from(std::vector<std::uint32_t> start,
                                                   const Neighbours& n) {
  std::vector<bool> reached(n.size(), false);
  for (std::uint32_t v : start) reached[v] = true;
  std::vector<std::vector<std::uint32_t>> rings;
  while (!start.empty()) {
    std::vector<std::uint32_t> next;
    for (std::uint32_t v : start) {
      for (std::uint32_t w : n[v]) {
        if (!reached[w]) reached[w] = true, next.push_back(w);
      }
    }
    rings.push_back(std::move(start));
    start = std::move(next);
  }
  return rings;
}

RingPolyline centres_and_radii(const std::vector<Eigen::Vector3d>& p,
                               const std::vector<std::vector<std::uint32_t>>& rings) {
  RingPolyline out;
  for (const auto& ring : rings) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::uint32_t v : ring) c += p[v];
    c /= static_cast<double>(ring.size());
    std::vector<double> d;
    for (std::uint32_t v : ring) d.push_back((p[v] - c).norm());
    // The median: a cap's centre vertex, reached with its rim, does not shrink the radius.
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    out.centres.push_back(c);
    out.radii_m.push_back(d[d.size() / 2]);
  }
  return out;
}

// A cap's centre vertex reached after its rim (a fan cap) is a ring in the rim's plane: dropped
// when it lies within a tenth of the rim's radius of the rim's centre.
void drop_flat_end_rings(RingPolyline& r) {
  const auto flat = [&r](std::size_t end, std::size_t inner) {
    return (r.centres[end] - r.centres[inner]).norm() < 0.1 * r.radii_m[inner];
  };
  if (r.centres.size() > 2 && flat(r.centres.size() - 1, r.centres.size() - 2)) {
    r.centres.pop_back(), r.radii_m.pop_back();
  }
  if (r.centres.size() > 2 && flat(0, 1)) {
    r.centres.erase(r.centres.begin()), r.radii_m.erase(r.radii_m.begin());
  }
}

}  // namespace

std::vector<WeldedPatch> connected_patches(const GroupedMesh& m,
                                           const std::vector<std::size_t>& group_faces) {
  std::map<std::array<double, 3>, std::uint32_t> id_of;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t f : group_faces) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t v : m.faces[f]) {
      const Eigen::Vector3d& p = m.vertices[v];
      const auto [it, fresh] =
          id_of.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(points.size()));
      if (fresh) points.push_back(p);
      if (face.empty() || face.back() != it->second) face.push_back(it->second);
    }
    if (face.size() > 1 && face.back() == face.front()) face.pop_back();
    if (face.size() >= 3) faces.push_back(std::move(face));
  }
  std::vector<std::uint32_t> root(points.size());
  std::iota(root.begin(), root.end(), 0u);
  for (const auto& f : faces) {
    for (std::uint32_t v : f) root[find_root(root, v)] = find_root(root, f[0]);
  }
  std::map<std::uint32_t, std::size_t> patch_of_root;
  std::vector<WeldedPatch> out;
  std::vector<std::map<std::uint32_t, std::uint32_t>> local;
  for (const auto& f : faces) {
    const auto [it, fresh] = patch_of_root.try_emplace(find_root(root, f[0]), out.size());
    if (fresh) out.emplace_back(), local.emplace_back();
    WeldedPatch& patch = out[it->second];
    std::vector<std::uint32_t> lf;
    for (std::uint32_t v : f) {
      const auto [lv, added] =
          local[it->second].try_emplace(v, static_cast<std::uint32_t>(patch.points.size()));
      if (added) patch.points.push_back(points[v]);
      lf.push_back(lv->second);
    }
    patch.faces.push_back(std::move(lf));
  }
  return out;
}

std::optional<RingPolyline> tube_rings(const WeldedPatch& patch) {
  std::map<Edge, int> uses = edge_uses(patch.faces);
  std::vector<std::uint32_t> start = one_boundary_loop(uses, patch.points.size());
  if (start.empty()) {
    // Closed by polygon caps: the tube's sides are the faces of at most four corners.
    std::vector<std::vector<std::uint32_t>> sides;
    for (const auto& f : patch.faces) {
      if (f.size() <= 4) sides.push_back(f);
    }
    start = one_boundary_loop(edge_uses(sides), patch.points.size());
  }
  if (start.empty()) start = lowest_end(patch.points);
  RingPolyline r =
      centres_and_radii(patch.points, rings_from(start, neighbours_of(uses, patch.points.size())));
  drop_flat_end_rings(r);
  if (r.centres.size() < 2) return std::nullopt;
  const double largest = *std::max_element(r.radii_m.begin(), r.radii_m.end());
  double span = 0.0;
  for (const Eigen::Vector3d& c : r.centres) span = std::max(span, (c - r.centres[0]).norm());
  if (span < 0.5 * largest) return std::nullopt;
  return r;
}

}  // namespace fspm::scans
