#include "stages/branch_mesh.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "fspm/error.hpp"

namespace fspm::stages {
namespace {

struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
    return static_cast<std::size_t>(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
  }
};

// Representative of each vertex: the first vertex within `tol` of it, found among the vertices
// already seen in the 27 grid cells of side `tol` around it.
std::vector<std::uint32_t> weld_map(const std::vector<Eigen::Vector3d>& v, double tol) {
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>, CellHash> grid;
  grid.reserve(v.size());
  std::vector<std::uint32_t> rep(v.size());
  const auto cell_of = [tol](const Eigen::Vector3d& p) {
    return std::array<std::int64_t, 3>{static_cast<std::int64_t>(std::floor(p.x() / tol)),
                                       static_cast<std::int64_t>(std::floor(p.y() / tol)),
                                       static_cast<std::int64_t>(std::floor(p.z() / tol))};
  };
  for (std::uint32_t i = 0; i < v.size(); ++i) {
    const auto c = cell_of(v[i]);
    rep[i] = i;
    for (int k = 0; k < 27 && rep[i] == i; ++k) {
      const std::array<std::int64_t, 3> n{c[0] + k % 3 - 1, c[1] + k / 3 % 3 - 1, c[2] + k / 9 - 1};
      const auto it = grid.find(n);
      if (it == grid.end()) continue;
      for (const std::uint32_t j : it->second) {
        if ((v[j] - v[i]).squaredNorm() <= tol * tol) {
          rep[i] = j;
          break;
        }
      }
    }
    if (rep[i] == i) grid[c].push_back(i);
  }
  return rep;
}

}  // namespace

BranchMesh weld_branch_mesh(const std::vector<Eigen::Vector3d>& vertices,
                            const std::vector<std::vector<std::uint32_t>>& faces,
                            double tolerance_fraction) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Eigen::Vector3d& p : vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double diagonal = vertices.empty() ? 0.0 : (hi - lo).norm();
  const double tol = std::max(diagonal * tolerance_fraction, 1e-300);
  const std::vector<std::uint32_t> rep = weld_map(vertices, tol);
  BranchMesh out;
  std::vector<std::uint32_t> index(vertices.size(), UINT32_MAX);
  const auto use = [&](std::uint32_t i) {
    const std::uint32_t r = rep[i];
    if (index[r] == UINT32_MAX) {
      index[r] = static_cast<std::uint32_t>(out.vertices.size());
      out.vertices.push_back(vertices[r]);
    }
    return index[r];
  };
  for (std::size_t f = 0; f < faces.size(); ++f) {
    for (const std::uint32_t i : faces[f]) {
      if (i >= vertices.size()) {
        throw ValueError("face " + std::to_string(f) + " names vertex " + std::to_string(i) +
                         " of " + std::to_string(vertices.size()));
      }
    }
    for (std::size_t k = 1; k + 1 < faces[f].size(); ++k) {
      const std::uint32_t a = rep[faces[f][0]], b = rep[faces[f][k]], c = rep[faces[f][k + 1]];
      if (a == b || b == c || a == c) continue;
      out.triangles.push_back({use(a), use(b), use(c)});
    }
  }
  if (out.triangles.empty()) throw ValueError("the mesh has no triangle (after welding)");
  return out;
}

}  // namespace fspm::stages
