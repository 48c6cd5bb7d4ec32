// Stochastic pruning: leaves in random order, a prefix drawn and enlarged (Cook et al. 2007).
#include "graphics/stochastic_pruning.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

// Appends the triangles `tris` of `mesh` (with their vertices, attributes and materials) to out.
void append_triangles(const TriangleMesh& mesh, const std::vector<std::size_t>& tris,
                      TriangleMesh& out) {
  if (out.attributes.empty()) {
    for (const auto& a : mesh.attributes) out.attributes.push_back({a.name, {}});
  }
  std::unordered_map<std::uint32_t, std::uint32_t> remap;
  for (std::size_t t : tris) {
    TriangleMesh::Triangle tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      auto [it, fresh] = remap.emplace(v, static_cast<std::uint32_t>(out.positions.size()));
      if (fresh) {
        out.positions.push_back(mesh.positions[v]);
        out.normals.push_back(mesh.normals[v]);
        out.uvs.push_back(mesh.uvs[v]);
        for (std::size_t a = 0; a < mesh.attributes.size(); ++a) {
          out.attributes[a].values.push_back(mesh.attributes[a].values[v]);
        }
      }
      tri[k] = it->second;
    }
    out.triangles.push_back(tri);
    out.materials.push_back(mesh.materials[t]);
  }
}

// Leaf triangles grouped by shared vertices (union-find over vertex indices).
std::vector<std::vector<std::size_t>> leaf_groups(const TriangleMesh& mesh,
                                                  std::vector<std::size_t>& others) {
  std::vector<std::uint32_t> up(mesh.vertex_count());
  std::iota(up.begin(), up.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (up[x] != x) x = up[x] = up[up[x]];
    return x;
  };
  std::vector<std::size_t> leaf_tris;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != Material::kLeaf) {
      others.push_back(t);
      continue;
    }
    leaf_tris.push_back(t);
    const auto& tri = mesh.triangles[t];
    up[find(tri[0])] = find(tri[1]);
    up[find(tri[1])] = find(tri[2]);
  }
  std::unordered_map<std::uint32_t, std::size_t> group_of;
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t t : leaf_tris) {
    auto [it, fresh] = group_of.emplace(find(mesh.triangles[t][0]), groups.size());
    if (fresh) groups.emplace_back();
    groups[it->second].push_back(t);
  }
  return groups;
}

}  // namespace

LeafBuffer make_leaf_buffer(const TriangleMesh& mesh, std::mt19937_64& rng) {
  std::vector<std::size_t> others;
  std::vector<std::vector<std::size_t>> groups = leaf_groups(mesh, others);
  std::shuffle(groups.begin(), groups.end(), rng);
  LeafBuffer b;
  append_triangles(mesh, others, b.bark);
  for (const auto& g : groups) {
    append_triangles(mesh, g, b.leaves);
    b.leaf_end.push_back(b.leaves.triangle_count());
  }
  return b;
}

std::size_t pruned_leaf_count(std::size_t leaves, double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) {
    throw ValueError("the share of leaves drawn must lie in [0, 1]");
  }
  if (leaves == 0 || fraction == 0.0) return 0;
  const auto n = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(leaves)));
  return std::clamp<std::size_t>(n, 1, leaves);
}

double pruning_fraction(double distance_m, double reference_distance_m) {
  if (!(reference_distance_m > 0.0) || !(distance_m >= 0.0)) {
    throw ValueError("pruning distances must be positive");
  }
  if (distance_m <= reference_distance_m) return 1.0;
  const double r = reference_distance_m / distance_m;
  return r * r;
}

TriangleMesh pruned_mesh(const LeafBuffer& b, std::size_t count) {
  count = std::min(count, b.leaf_count());
  TriangleMesh out = b.bark;
  if (count == 0) return out;
  std::vector<std::size_t> tris(b.leaf_end[count - 1]);
  std::iota(tris.begin(), tris.end(), std::size_t{0});
  TriangleMesh kept;
  append_triangles(b.leaves, tris, kept);
  // Enlarge each kept leaf about its centroid (vertices of leaf k are contiguous and precede
  // those of leaf k + 1, as append_triangles adds them in triangle order).
  const float scale = static_cast<float>(
      std::sqrt(static_cast<double>(b.leaf_count()) / static_cast<double>(count)));
  std::size_t tri_begin = 0;
  for (std::size_t k = 0; k < count; ++k) {
    std::uint32_t lo = UINT32_MAX, hi = 0;
    for (std::size_t t = tri_begin; t < b.leaf_end[k]; ++t) {
      for (auto v : kept.triangles[t]) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
    Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
    for (std::uint32_t v = lo; v <= hi; ++v) centroid += kept.positions[v];
    centroid /= static_cast<float>(hi - lo + 1);
    for (std::uint32_t v = lo; v <= hi; ++v) {
      kept.positions[v] = centroid + scale * (kept.positions[v] - centroid);
    }
    tri_begin = b.leaf_end[k];
  }
  out.append(kept);
  return out;
}

}  // namespace fspm::graphics
