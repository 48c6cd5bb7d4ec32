#include "scans/grouped_mesh_skeleton.hpp"

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "fspm/error.hpp"

namespace fspm::scans {
namespace {

struct Section {
  Eigen::Vector3d mid;
  double radius;
};

// Midpoint and inscribed radius of each face of group g, in file order.
std::vector<Section> sections(const GroupedMesh& m, std::uint32_t g) {
  std::vector<Section> out;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    if (m.face_group[f] != g) continue;
    Eigen::Vector3d mid = Eigen::Vector3d::Zero();
    for (std::uint32_t v : m.faces[f]) mid += m.vertices[v];
    mid /= static_cast<double>(m.faces[f].size());
    double r = 0.0;
    for (std::uint32_t v : m.faces[f]) r += (m.vertices[v] - mid).norm();
    const double n = static_cast<double>(m.faces[f].size());
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

TreeGraph grouped_mesh_skeleton(const GroupedMesh& m, const std::string& path) {
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
