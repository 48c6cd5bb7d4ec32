#include "scans/grouped_mesh_skeleton.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <numeric>
#include <optional>
#include <set>

#include "fspm/error.hpp"
#include "scans/tube_skeleton.hpp"

namespace fspm::scans {
namespace {

struct Section {
  Eigen::Vector3d mid;
  double radius;
};

// Newell's normal of a polygon (not normalised; zero for a degenerate one).
Eigen::Vector3d newell_normal(const GroupedMesh& m, const std::vector<std::uint32_t>& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < face.size(); ++k) {
    const Eigen::Vector3d& a = m.vertices[face[k]];
    const Eigen::Vector3d& b = m.vertices[face[(k + 1) % face.size()]];
    n += Eigen::Vector3d((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
                         (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

// Two faces that share an edge lie in one plane when their normals are parallel (within about
// 0.1 degree, the rounding of single-precision coordinates).
bool coplanar(const GroupedMesh& m, const std::vector<std::uint32_t>& a,
              const std::vector<std::uint32_t>& b) {
  const Eigen::Vector3d na = newell_normal(m, a), nb = newell_normal(m, b);
  const double scale = na.norm() * nb.norm();
  return scale > 0.0 && std::abs(na.dot(nb)) >= (1.0 - 1e-6) * scale;
}

// The faces of group g that make one cross-section each: a face, joined with the faces that share
// an edge with it and lie in its plane (a polygon an exporter split into triangles, as glTF
// stores only triangles). Vertices are compared by position, since exporters repeat them per
// face. Cross-sections come in the order of their first face in the file.
std::vector<std::vector<Eigen::Vector3d>> cross_sections(const GroupedMesh& m, std::uint32_t g) {
  std::vector<std::size_t> faces;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (m.face_group[f] == g) faces.push_back(f);
  }
  std::map<std::array<double, 3>, std::uint32_t> id_of;  // one id per distinct position
  const auto id = [&](std::uint32_t v) {
    const Eigen::Vector3d& p = m.vertices[v];
    return id_of.try_emplace({p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(id_of.size()))
        .first->second;
  };
  std::vector<std::size_t> root(faces.size());
  std::iota(root.begin(), root.end(), std::size_t{0});
  const auto find = [&root](std::size_t i) {
    while (root[i] != i) i = root[i] = root[root[i]];
    return i;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> first_face_of_edge;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const std::vector<std::uint32_t>& f = m.faces[faces[i]];
    for (std::size_t k = 0; k < f.size(); ++k) {
      const std::uint32_t a = id(f[k]), b = id(f[(k + 1) % f.size()]);
      const auto [it, fresh] = first_face_of_edge.try_emplace(std::minmax(a, b), i);
      if (!fresh && coplanar(m, m.faces[faces[it->second]], f)) root[find(i)] = find(it->second);
    }
  }
  std::vector<std::vector<Eigen::Vector3d>> out;
  std::map<std::size_t, std::size_t> section_of_root;
  std::vector<std::set<std::uint32_t>> seen;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto [it, fresh] = section_of_root.try_emplace(find(i), out.size());
    if (fresh) out.emplace_back(), seen.emplace_back();
    for (std::uint32_t v : m.faces[faces[i]]) {
      if (seen[it->second].insert(id(v)).second) out[it->second].push_back(m.vertices[v]);
    }
  }
  return out;
}

// Midpoint and inscribed radius of each cross-section of group g, in file order: the radius of
// the regular n-gon whose corners are, on average, as far from the midpoint as the section's.
std::vector<Section> sections(const GroupedMesh& m, std::uint32_t g) {
  std::vector<Section> out;
  for (const std::vector<Eigen::Vector3d>& corners : cross_sections(m, g)) {
    Eigen::Vector3d mid = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : corners) mid += p;
    const double n = static_cast<double>(corners.size());
    mid /= n;
    double r = 0.0;
    for (const Eigen::Vector3d& p : corners) r += (p - mid).norm();
    out.push_back({mid, r / n * std::cos(std::numbers::pi / n)});
  }
  return out;
}

// The node of `levels_below` nearest to p.
NodeId nearest_node(const TreeGraph& t, const std::vector<NodeId>& candidates,
                    const Eigen::Vector3d& p) {
  NodeId best = kNoNode;
  double best_d = std::numeric_limits<double>::infinity();
  for (NodeId u : candidates) {
    const double d = (t.end(u) - p).squaredNorm();
    if (d < best_d) best_d = d, best = u;
  }
  return best;
}

}  // namespace

std::string group_level_name(const std::string& name) {
  std::size_t end = name.size();
  while (end > 0 && std::isdigit(static_cast<unsigned char>(name[end - 1]))) --end;
  return name.substr(0, end);
}

std::optional<std::vector<RingPolyline>> tube_branches(const GroupedMesh& m,
                                                       std::size_t* not_tubes) {
  std::vector<RingPolyline> tubes;
  std::size_t others = 0;
  // Faces by group name: an OBJ file may return to a group with a second `g` line.
  std::map<std::string, std::vector<std::size_t>> faces_of;
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    faces_of[m.group_names[m.face_group[f]]].push_back(f);
  for (const auto& [name, faces] : faces_of) {
    for (const WeldedPatch& patch : connected_patches(m, faces)) {
      std::optional<RingPolyline> r = tube_rings(patch);
      if (r) {
        tubes.push_back(std::move(*r));
      } else {
        ++others;
      }
    }
  }
  if (not_tubes != nullptr) *not_tubes = others;
  if (tubes.empty()) return std::nullopt;
  return tubes;
}

TreeGraph grouped_mesh_skeleton(const GroupedMesh& m, const std::string& path,
                                std::size_t* not_tubes) {
  if (not_tubes != nullptr) *not_tubes = 0;
  if (m.faces.empty()) {
    throw ValueError("the mesh has no faces; a point set gives a skeleton with fspm encode", path);
  }
  if (std::optional<std::vector<RingPolyline>> tubes = tube_branches(m, not_tubes)) {
    return tube_skeleton(*tubes, path);
  }
  std::vector<std::string> level_names;
  std::map<std::string, std::vector<std::uint32_t>> groups_of;  // level -> groups
  std::vector<bool> used(m.group_names.size(), false);
  for (std::uint32_t g : m.face_group) used[g] = true;
  for (std::uint32_t g = 0; g < m.group_names.size(); ++g) {
    if (!used[g]) continue;
    const std::string level = group_level_name(m.group_names[g]);
    if (!groups_of.count(level)) level_names.push_back(level);
    groups_of[level].push_back(g);
  }
  if (level_names.empty() || groups_of[level_names[0]].size() != 1) {
    throw ValueError("expected exactly one group (the trunk) in the first level of the mesh", path);
  }
  TreeGraph t;
  std::vector<NodeId> below, current;
  for (std::size_t level = 0; level < level_names.size(); ++level) {
    for (std::uint32_t g : groups_of[level_names[level]]) {
      const std::vector<Section> s = sections(m, g);
      if (level == 0 && s.size() < 2) {
        throw ValueError(
            "the trunk group '" + m.group_names[g] + "' needs at least two cross-sections", path);
      }
      NodeId parent = level == 0 ? kNoNode : nearest_node(t, below, s[0].mid);
      for (std::size_t k = level == 0 ? 1 : 0; k < s.size(); ++k) {
        NodeData d;
        d.start = k == 0 ? t.end(parent) : s[k - 1].mid;
        d.end = s[k].mid;
        d.radius = s[k].radius;
        d.order = static_cast<std::uint16_t>(level);
        parent = t.add_node(parent, d);
        current.push_back(parent);
      }
    }
    below = std::move(current);
    current.clear();
  }
  return t;
}

}  // namespace fspm::scans
