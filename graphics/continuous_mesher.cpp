// Continuous junctions after Reynolds et al., section 3.2: one tube per axis, knuckle rings where
// laterals leave, laterals grown out of the quad left open in the parent, bone weights per vertex.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/tree_traversal.hpp"
#include "graphics/bone_weights.hpp"
#include "graphics/parallel_transport.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::graphics {
namespace {

constexpr double kMinSegmentM = 1e-9;
constexpr double kTwoPi = 6.283185307179586;

// Reynolds expression 1: 1/x for x in [1, 4], rescaled to run from 1 at the root to 0 at the tip.
double reynolds_width(double t) { return (1.0 / (3.0 * t + 1.0) - 0.25) / 0.75; }

struct Hole {
  std::array<std::uint32_t, 4> vertices{};
  Eigen::Vector3d v0 =
      Eigen::Vector3d::UnitX();  // frame normal carried onto the lateral's first tangent
  double collar_m = 0.0;         // the lateral's first own ring, this far along its axis
  bool valid = false;
};

class Builder {
 public:
  Builder(const TreeGraph& tree, double reference_time)
      : tree_(tree), reference_time_(reference_time) {
    names_ = {kAttributeAge, kAttributeBirthTime, kAttributeOrder, kAttributePhysiologicalAge};
    for (const auto& n : tree.attribute_names()) {
      names_.push_back(n);
      user_.push_back(tree.attribute(n));
    }
    columns_.resize(names_.size());
  }

  std::uint32_t vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, float u, float v,
                       NodeId node, NodeId bone0, NodeId bone1) {
    mesh_.positions.push_back(p.cast<float>());
    mesh_.normals.push_back(n.normalized().cast<float>());
    mesh_.uvs.push_back({u, v});
    const double birth = tree_.birth_time(node);
    columns_[0].push_back(static_cast<float>(reference_time_ - birth));
    columns_[1].push_back(static_cast<float>(birth));
    columns_[2].push_back(static_cast<float>(tree_.order(node)));
    columns_[3].push_back(static_cast<float>(tree_.physiological_age(node)));
    for (std::size_t i = 0; i < user_.size(); ++i) {
      columns_[4 + i].push_back(static_cast<float>(user_[i][node]));
    }
    weights_.push_back(joint_weights(bone0, bone1));
    alias_.push_back(kNoAlias);
    if (mesh_.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
      throw ValueError("mesh would need more than 2^32 vertices; raise the edge length");
    }
    return static_cast<std::uint32_t>(mesh_.positions.size() - 1);
  }

  // A second vertex at the position of `original` (another normal): it is the same point of the
  // surface, so it ends with the original's bone weights.
  std::uint32_t copy(std::uint32_t original, const Eigen::Vector3d& n, float u, float v,
                     NodeId node) {
    const std::uint32_t id =
        vertex(mesh_.positions[original].cast<double>(), n, u, v, node, node, node);
    alias_[id] = root(original);
    return id;
  }

  // Reynolds: a vertex shared by a lateral's root ring gains the lateral's bone at 1.0.
  void add_influence(std::uint32_t v, NodeId bone, float weight) {
    weights_[root(v)].add(bone, weight);
  }

  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh_.triangles.push_back({a, b, c});
    mesh_.materials.push_back(Material::kBark);
  }

  const Eigen::Vector3f& position(std::uint32_t v) const { return mesh_.positions[v]; }

  TriangleMesh finish() {
    for (std::size_t i = 0; i < names_.size(); ++i) {
      mesh_.attributes.push_back({names_[i], std::move(columns_[i])});
    }
    for (BoneWeights& w : weights_) w.normalise();
    for (std::size_t v = 0; v < weights_.size(); ++v) {
      if (alias_[v] != kNoAlias) weights_[v] = weights_[alias_[v]];
    }
    write_bone_attributes(weights_, mesh_);
    return std::move(mesh_);
  }

 private:
  const TreeGraph& tree_;
  double reference_time_;
  std::vector<std::string> names_;
  std::vector<std::span<const double>> user_;
  std::vector<std::vector<float>> columns_;
  std::uint32_t root(std::uint32_t v) const { return alias_[v] == kNoAlias ? v : alias_[v]; }

  static constexpr std::uint32_t kNoAlias = std::numeric_limits<std::uint32_t>::max();
  std::vector<BoneWeights> weights_;
  std::vector<std::uint32_t> alias_;
  TriangleMesh mesh_;
};

Eigen::Vector3d seg(const TreeGraph& t, NodeId n) { return t.end(n) - t.start(n); }

struct Ring {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d tangent = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d v = Eigen::Vector3d::UnitX();
  double radius = 0.0;
  double along = 0.0;
  NodeId node = kNoNode, bone0 = kNoNode, bone1 = kNoNode;  // bone0 == bone1: a branch end
  std::vector<std::size_t> laterals;  // axes leaving through the strip above this ring
};

}  // namespace

TriangleMesh mesh_tree_continuous(const TreeGraph& tree, const MeshOptions& options) {
  MeshOptions leaves_only = options;
  leaves_only.junctions = JunctionMode::kSeparate;
  leaves_only.bark = false;
  leaves_only.leaf_bones = true;
  TriangleMesh leaves = mesh_tree(tree, leaves_only);  // validates the options too
  const std::size_t n = tree.size();
  if (n == 0 || !options.bark) return leaves;

  // Kept internodes as a forest with their orders, so fspm::axes follows the branching orders.
  std::vector<char> kept(n);
  double latest = -std::numeric_limits<double>::infinity();
  for (NodeId id = 0; id < n; ++id) {
    const NodeId p = tree.parent(id);
    kept[id] = tree.birth_time(id) <= options.max_birth_time && (p == kNoNode || kept[p]);
    if (kept[id]) latest = std::max(latest, tree.birth_time(id));
  }
  const double reference_time = std::isinf(options.max_birth_time)
                                    ? (std::isinf(latest) ? 0.0 : latest)
                                    : options.max_birth_time;
  TreeGraph forest;
  std::vector<NodeId> to_tree, nearest(n, kNoNode), to_forest(n, kNoNode);
  for (NodeId id = 0; id < n; ++id) {
    const NodeId p = tree.parent(id);
    const NodeId above = p == kNoNode ? kNoNode : nearest[p];
    if (!kept[id] || tree.kind(id) != OrganKind::kInternode ||
        (above == kNoNode && !forest.empty())) {
      nearest[id] = above;
      continue;
    }
    nearest[id] = id;
    NodeData d;
    d.order = tree.order(id);
    to_forest[id] = forest.add_node(above == kNoNode ? kNoNode : to_forest[above], d);
    to_tree.push_back(id);
  }
  std::vector<std::vector<NodeId>> node_axes = axes(forest);
  for (auto& a : node_axes) {
    for (NodeId& id : a) id = to_tree[id];
  }
  // Laterals by the node they leave from.
  std::vector<std::vector<std::size_t>> laterals_at(n);
  for (std::size_t a = 0; a < node_axes.size(); ++a) {
    const NodeId p = tree.parent(node_axes[a].front());
    if (p != kNoNode && nearest[p] != kNoNode) laterals_at[nearest[p]].push_back(a);
  }

  Builder b(tree, reference_time);
  std::vector<Hole> holes(node_axes.size());
  std::vector<Eigen::Vector3d> tip_v(n), tip_t(n);
  std::vector<char> has_tip(n, 0);
  std::vector<double> width_at_node(n, 0.0);

  for (std::size_t a = 0; a < node_axes.size(); ++a) {
    std::vector<NodeId> segs;
    for (NodeId id : node_axes[a]) {
      if (seg(tree, id).norm() > kMinSegmentM) segs.push_back(id);
    }
    if (segs.empty()) continue;
    const std::size_t m = segs.size();
    double total = 0.0;
    for (NodeId id : segs) total += seg(tree, id).norm();
    const NodeId attach = tree.parent(node_axes[a].front()) == kNoNode
                              ? kNoNode
                              : nearest[tree.parent(node_axes[a].front())];
    const double root_width =
        options.reynolds_width && attach != kNoNode && width_at_node[attach] > 0
            ? width_at_node[attach]
            : tree.radius(segs[0]);
    auto radius_at = [&](NodeId node, double along) {
      const double r =
          options.reynolds_width ? root_width * reynolds_width(along / total) : tree.radius(node);
      return std::max(r, options.min_radius_m);
    };
    const double distance =
        options.camera_m ? (tree.start(segs[0]) - *options.camera_m).norm() : 0.0;
    const int s = sides_for_radius(radius_at(segs[0], 0.0), options, distance);

    // Rings at the joints (bisector tangents), plus a knuckle ring above every joint that
    // laterals leave from, at the lateral's width (Reynolds: "two rings ... separated by the
    // width of the branch").
    std::vector<Ring> rings;
    double along = 0.0;
    for (std::size_t j = 0; j <= m; ++j) {
      Ring r;
      const NodeId below = j > 0 ? segs[j - 1] : segs[0];
      const NodeId above = j < m ? segs[j] : segs[m - 1];
      r.center = j < m ? tree.start(above) : tree.end(below);
      const Eigen::Vector3d tb = seg(tree, below).normalized(), ta = seg(tree, above).normalized();
      r.tangent = (tb + ta).norm() > 1e-9 ? (tb + ta).normalized() : ta;
      r.along = along;
      r.node = j < m ? above : below;
      r.bone0 = below;
      r.bone1 = above;
      r.radius = radius_at(r.node, along);
      width_at_node[below] = r.radius;
      rings.push_back(r);
      if (j > 0 && j < m && !laterals_at[below].empty()) {
        // The knuckle is as tall as the lateral is wide, and twice the height at which the
        // lateral's axis leaves the parent's surface, so that axis runs through the open quad.
        double h = 0.0;
        for (std::size_t c : laterals_at[below]) {
          const NodeId c0 = node_axes[c].front();
          const double cos_t = std::clamp(seg(tree, c0).normalized().dot(ta), -1.0, 1.0);
          const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
          const double exit = sin_t > 1e-6 ? r.radius * std::max(cos_t, 0.0) / sin_t : 1e9;
          h = std::max({h, 2.0 * tree.radius(c0), 2.0 * exit});
        }
        const double len = seg(tree, above).norm();
        h = std::min(std::max(h, 0.05 * len), 0.5 * len);
        Ring k = r;
        k.center = r.center + h * ta;
        k.tangent = ta;
        k.along = along + h;
        k.node = above;
        k.bone0 = k.bone1 = above;
        k.radius = radius_at(above, along + h);
        rings.back().laterals = laterals_at[below];
        rings.push_back(k);
      }
      if (j < m) along += seg(tree, above).norm();
    }
    width_at_node[segs[m - 1]] = rings.back().radius;

    if (holes[a].valid && holes[a].collar_m > 0.0) {
      Ring c = rings[0];
      const Eigen::Vector3d t0 = seg(tree, segs[0]).normalized();
      c.center = rings[0].center + holes[a].collar_m * t0;
      c.tangent = t0;
      c.along = holes[a].collar_m;
      c.bone0 = c.bone1 = segs[0];
      c.radius = radius_at(segs[0], c.along);
      rings.insert(rings.begin() + 1, c);
    }
    std::vector<Eigen::Vector3d> tangents;
    for (const Ring& r : rings) tangents.push_back(r.tangent);
    Eigen::Vector3d v0 = any_perpendicular(tangents[0]);
    if (holes[a].valid) {
      v0 = holes[a].v0;
    } else if (attach != kNoNode && has_tip[attach]) {
      v0 = transport(tip_v[attach], tip_t[attach], tangents[0]);
    }
    const std::vector<Eigen::Vector3d> vs = parallel_transport_normals(tangents, v0);
    for (std::size_t i = 0; i < rings.size(); ++i) rings[i].v = vs[i];
    tip_v[segs[m - 1]] = vs.back();
    tip_t[segs[m - 1]] = tangents.back();
    has_tip[segs[m - 1]] = 1;

    // Ring vertices (s + 1 with the seam repeated).
    const double v_scale = 1.0 / (kTwoPi * std::max(rings[0].radius, options.min_radius_m));
    std::vector<std::uint32_t> first(rings.size());
    const bool from_hole = holes[a].valid;  // ring 0 is then the parent's open quad
    for (std::size_t i = from_hole ? 1 : 0; i < rings.size(); ++i) {
      const Ring& r = rings[i];
      const Eigen::Vector3d w = r.tangent.cross(r.v);
      for (int k = 0; k < s; ++k) {
        const double ang = kTwoPi * k / s;
        const Eigen::Vector3d dir = std::cos(ang) * r.v + std::sin(ang) * w;
        const std::uint32_t id =
            b.vertex(r.center + r.radius * dir, dir, static_cast<float>(k) / s,
                     static_cast<float>(r.along * v_scale), r.node, r.bone0, r.bone1);
        if (k == 0) first[i] = id;
      }
      // The seam: the first vertex again with u = 1, the same point of the surface.
      b.copy(first[i], r.v, 1.0f, static_cast<float>(r.along * v_scale), r.node);
    }

    // Holes for laterals, decided before the walls so their quads are left open.
    std::vector<std::vector<int>> open_quads(rings.size());
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
      for (std::size_t c : rings[i].laterals) {
        const NodeId c0 = node_axes[c].front();
        if (seg(tree, c0).norm() <= kMinSegmentM) continue;
        const Ring& r = rings[i];
        const Eigen::Vector3d tc = seg(tree, c0).normalized();
        const Eigen::Vector3d w = r.tangent.cross(r.v);
        double phi = std::atan2(tc.dot(w), tc.dot(r.v));
        if (phi < 0) phi += kTwoPi;
        const int k = std::min(static_cast<int>(phi / (kTwoPi / s)), s - 1);
        auto& taken = open_quads[i];
        if (std::find(taken.begin(), taken.end(), k) != taken.end()) continue;
        Hole h;
        h.vertices = {first[i] + k, first[i] + k + 1, first[i + 1] + k + 1, first[i + 1] + k};
        h.v0 = transport(r.v, r.tangent, tc);
        // The lateral must leave the hole outwards: its first ring beyond the hole, and the hole
        // corners all around its axis (each angular gap below pi).
        const Eigen::Vector3d origin = tree.start(c0);
        const Eigen::Vector3d hw = tc.cross(h.v0);
        std::array<double, 4> ang{};
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int q = 0; q < 4; ++q) {
          const Eigen::Vector3d p = b.position(h.vertices[q]).cast<double>();
          centroid += 0.25 * p;
          const Eigen::Vector3d d = p - origin;
          ang[q] = std::atan2(d.dot(hw), d.dot(h.v0));
        }
        std::array<double, 4> sorted = ang;
        std::sort(sorted.begin(), sorted.end());
        double max_gap = sorted[0] + kTwoPi - sorted[3];
        for (int q = 0; q < 3; ++q) max_gap = std::max(max_gap, sorted[q + 1] - sorted[q]);
        // A collar ring just outside the parent keeps the zipped triangles short and tube-like.
        const double sin_t = r.tangent.cross(tc).norm();
        const double collar = (sin_t > 1e-6 ? r.radius / sin_t : 1e9) + tree.radius(c0);
        const double c0_len = seg(tree, c0).norm();
        h.collar_m = collar < 0.6 * c0_len ? collar : 0.0;
        const double beyond =
            (origin + (h.collar_m > 0.0 ? h.collar_m : c0_len) * tc - centroid).dot(tc);
        if (max_gap >= M_PI - 1e-3 || beyond <= 0.2 * tree.radius(c0)) continue;
        taken.push_back(k);
        h.valid = true;
        holes[c] = h;
      }
    }

    // Walls: (a, b, d) and (a, d, c) face outwards, as in the chain mesher.
    for (std::size_t i = from_hole ? 1 : 0; i + 1 < rings.size(); ++i) {
      for (int k = 0; k < s; ++k) {
        if (std::find(open_quads[i].begin(), open_quads[i].end(), k) != open_quads[i].end()) {
          continue;
        }
        const std::uint32_t p = first[i] + k, q = p + 1, r = first[i + 1] + k, t = r + 1;
        b.triangle(p, q, t);
        b.triangle(p, t, r);
      }
    }

    // The base: zipped onto the parent's hole, or closed by a cap.
    if (from_hole) {
      const Hole& h = holes[a];
      const Eigen::Vector3d origin = tree.start(segs[0]);
      const Eigen::Vector3d hw = tangents[0].cross(vs[0]);
      std::array<std::pair<double, std::uint32_t>, 4> hv;
      for (int q = 0; q < 4; ++q) {
        const Eigen::Vector3d p = b.position(h.vertices[q]).cast<double>();
        const Eigen::Vector3d d = p - origin;
        double ang = std::atan2(d.dot(hw), d.dot(vs[0]));
        if (ang < 0) ang += kTwoPi;
        // The hole's corners again, at the same positions, with normals radial to the lateral
        // (the parent's radial normals would shade the collar as if it faced the trunk).
        const Eigen::Vector3d radial = d - d.dot(tangents[0]) * tangents[0];
        b.add_influence(h.vertices[q], segs[0], 1.0f);
        hv[q] = {ang,
                 b.copy(h.vertices[q], radial, static_cast<float>(ang / kTwoPi), 0.0f, segs[0])};
      }
      std::sort(hv.begin(), hv.end());
      // Hole loop h0..h3 then h0 again at +2 pi; ring 1 loop 0..s (seam at 2 pi). Advance on
      // whichever loop has the smaller next angle (lower loop = hole, upper = ring 1).
      std::vector<std::pair<double, std::uint32_t>> lower(hv.begin(), hv.end());
      lower.push_back({hv[0].first + kTwoPi, hv[0].second});
      const std::uint32_t upper0 = first[1];
      std::size_t i = 0, j = 0;
      while (i + 1 < lower.size() || j < static_cast<std::size_t>(s)) {
        const double next_upper = kTwoPi * static_cast<double>(j + 1) / s;
        const bool take_upper = j < static_cast<std::size_t>(s) &&
                                (i + 1 >= lower.size() || next_upper <= lower[i + 1].first);
        if (take_upper) {
          b.triangle(lower[i].second, upper0 + static_cast<std::uint32_t>(j + 1),
                     upper0 + static_cast<std::uint32_t>(j));
          ++j;
        } else {
          b.triangle(lower[i].second, lower[i + 1].second, upper0 + static_cast<std::uint32_t>(j));
          ++i;
        }
      }
    }
    for (int end = from_hole ? 1 : 0; end < 2; ++end) {
      const std::size_t ri = end == 0 ? 0 : rings.size() - 1;
      const Ring& r = rings[ri];
      const Eigen::Vector3d nrm = end == 0 ? -r.tangent : r.tangent;
      const std::uint32_t hub = b.vertex(r.center, nrm, 0.5f, 0.5f, r.node, r.bone0, r.bone1);
      for (int k = 0; k < s; ++k) b.copy(first[ri] + k, nrm, 0.5f, 0.5f, r.node);
      for (int k = 0; k < s; ++k) {
        const std::uint32_t p = hub + 1 + k, q = hub + 1 + (k + 1) % s;
        if (end == 0) {
          b.triangle(hub, q, p);
        } else {
          b.triangle(hub, p, q);
        }
      }
    }
  }
  TriangleMesh bark = b.finish();
  bark.append(leaves);
  return bark;
}

}  // namespace fspm::graphics
