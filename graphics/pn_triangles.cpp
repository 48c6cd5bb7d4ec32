// Curved PN triangles (Vlachos et al. 2001) and their uniform tessellation on the CPU.
#include "graphics/pn_triangles.hpp"

#include <Eigen/Geometry>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

// b_ij: corner i moved a third of the way to corner j, projected onto i's tangent plane.
Eigen::Vector3f edge_point(const Eigen::Vector3f& pi, const Eigen::Vector3f& pj,
                           const Eigen::Vector3f& ni) {
  const float w = (pj - pi).dot(ni);
  return (2.0f * pi + pj - w * ni) / 3.0f;
}

// n_ij: the mean normal reflected across the plane perpendicular to the edge.
Eigen::Vector3f edge_normal(const Eigen::Vector3f& pi, const Eigen::Vector3f& pj,
                            const Eigen::Vector3f& ni, const Eigen::Vector3f& nj) {
  const Eigen::Vector3f d = pj - pi;
  const float len2 = d.squaredNorm();
  const float v = len2 > 0.0f ? 2.0f * d.dot(ni + nj) / len2 : 0.0f;
  const Eigen::Vector3f h = ni + nj - v * d;
  return h.norm() > 0.0f ? Eigen::Vector3f(h.normalized()) : ni;
}

}  // namespace

PnTriangle pn_triangle(const std::array<Eigen::Vector3f, 3>& p,
                       const std::array<Eigen::Vector3f, 3>& n) {
  PnTriangle t;
  t.b[0] = p[0];
  t.b[1] = p[1];
  t.b[2] = p[2];
  t.b[3] = edge_point(p[0], p[1], n[0]);  // b210
  t.b[4] = edge_point(p[1], p[0], n[1]);  // b120
  t.b[5] = edge_point(p[1], p[2], n[1]);  // b021
  t.b[6] = edge_point(p[2], p[1], n[2]);  // b012
  t.b[7] = edge_point(p[2], p[0], n[2]);  // b102
  t.b[8] = edge_point(p[0], p[2], n[0]);  // b201
  Eigen::Vector3f e = Eigen::Vector3f::Zero();
  for (int k = 3; k < 9; ++k) e += t.b[static_cast<std::size_t>(k)] / 6.0f;
  const Eigen::Vector3f v = (p[0] + p[1] + p[2]) / 3.0f;
  t.b[9] = e + 0.5f * (e - v);  // b111
  t.n = {n[0],
         n[1],
         n[2],
         edge_normal(p[0], p[1], n[0], n[1]),
         edge_normal(p[1], p[2], n[1], n[2]),
         edge_normal(p[2], p[0], n[2], n[0])};
  return t;
}

Eigen::Vector3f pn_point(const PnTriangle& t, const Eigen::Vector3f& w) {
  const float a = w.x(), b = w.y(), c = w.z();
  return t.b[0] * (a * a * a) + t.b[1] * (b * b * b) + t.b[2] * (c * c * c) +
         3.0f * (t.b[3] * (a * a * b) + t.b[4] * (a * b * b) + t.b[5] * (b * b * c) +
                 t.b[6] * (b * c * c) + t.b[7] * (a * c * c) + t.b[8] * (a * a * c)) +
         6.0f * a * b * c * t.b[9];
}

Eigen::Vector3f pn_normal(const PnTriangle& t, const Eigen::Vector3f& w) {
  const float a = w.x(), b = w.y(), c = w.z();
  const Eigen::Vector3f n = t.n[0] * (a * a) + t.n[1] * (b * b) + t.n[2] * (c * c) +
                            t.n[3] * (a * b) + t.n[4] * (b * c) + t.n[5] * (c * a);
  return n.norm() > 0.0f ? Eigen::Vector3f(n.normalized()) : t.n[0];
}

TriangleMesh tessellate_pn(const TriangleMesh& mesh, int level) {
  if (level < 1) throw ValueError("a tessellation level is at least 1");
  if (level == 1) return mesh;
  TriangleMesh out;
  out.attributes = mesh.attributes;
  for (auto& a : out.attributes) a.values.clear();
  const bool has_uvs = mesh.uvs.size() == mesh.positions.size();
  const float step = 1.0f / static_cast<float>(level);
  for (std::size_t f = 0; f < mesh.triangle_count(); ++f) {
    const auto& tri = mesh.triangles[f];
    const PnTriangle pn =
        pn_triangle({mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]},
                    {mesh.normals[tri[0]], mesh.normals[tri[1]], mesh.normals[tri[2]]});
    const auto first = static_cast<std::uint32_t>(out.positions.size());
    // Grid vertex (i, j): weights ((level - i - j), i, j) / level, row by row in i.
    for (int i = 0; i <= level; ++i) {
      for (int j = 0; j + i <= level; ++j) {
        const Eigen::Vector3f w(static_cast<float>(level - i - j) * step,
                                static_cast<float>(i) * step, static_cast<float>(j) * step);
        out.positions.push_back(pn_point(pn, w));
        out.normals.push_back(pn_normal(pn, w));
        if (has_uvs) {
          out.uvs.push_back(w.x() * mesh.uvs[tri[0]] + w.y() * mesh.uvs[tri[1]] +
                            w.z() * mesh.uvs[tri[2]]);
        }
        for (std::size_t k = 0; k < mesh.attributes.size(); ++k) {
          const auto& v = mesh.attributes[k].values;
          out.attributes[k].values.push_back(w.x() * v[tri[0]] + w.y() * v[tri[1]] +
                                             w.z() * v[tri[2]]);
        }
      }
    }
    // Row i holds level - i + 1 vertices; the index of (i, j) is row_start(i) + j.
    const auto index = [&](int i, int j) {
      return first + static_cast<std::uint32_t>(i * (level + 1) - i * (i - 1) / 2 + j);
    };
    for (int i = 0; i < level; ++i) {
      for (int j = 0; j + i < level; ++j) {
        out.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
        out.materials.push_back(mesh.materials[f]);
        if (j + i + 1 < level) {
          out.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
          out.materials.push_back(mesh.materials[f]);
        }
      }
    }
  }
  return out;
}

}  // namespace fspm::graphics
