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

// The axes of the kept internodes (fspm::axes on the forest they form, so an axis follows the
// branching orders), the nearest kept internode at or above every node, and the axes leaving
// each node.
struct AxisLayout {
  std::vector<std::vector<NodeId>> axes;  // tree ids, root first
  std::vector<NodeId> nearest;            // kNoNode above the first kept internode
  std::vector<std::vector<std::size_t>> laterals_at;
  double reference_time = 0.0;  // the age of a vertex is this minus its node's birth time
};

AxisLayout layout_axes(const TreeGraph& tree, double max_birth_time) {
  const std::size_t n = tree.size();
  std::vector<char> kept(n);
  double latest = -std::numeric_limits<double>::infinity();
  for (NodeId id = 0; id < n; ++id) {
    const NodeId p = tree.parent(id);
    kept[id] = tree.birth_time(id) <= max_birth_time && (p == kNoNode || kept[p]);
    if (kept[id]) latest = std::max(latest, tree.birth_time(id));
  }
  AxisLayout layout;
  layout.reference_time =
      std::isinf(max_birth_time) ? (std::isinf(latest) ? 0.0 : latest) : max_birth_time;
  TreeGraph forest;
  std::vector<NodeId> to_tree, to_forest(n, kNoNode);
  layout.nearest.assign(n, kNoNode);
  for (NodeId id = 0; id < n; ++id) {
    const NodeId p = tree.parent(id);
    const NodeId above = p == kNoNode ? kNoNode : layout.nearest[p];
    if (!kept[id] || tree.kind(id) != OrganKind::kInternode ||
        (above == kNoNode && !forest.empty())) {
      layout.nearest[id] = above;
      continue;
    }
    layout.nearest[id] = id;
    NodeData d;
    d.order = tree.order(id);
    to_forest[id] = forest.add_node(above == kNoNode ? kNoNode : to_forest[above], d);
    to_tree.push_back(id);
  }
  layout.axes = axes(forest);
  for (auto& a : layout.axes) {
    for (NodeId& id : a) id = to_tree[id];
  }
  layout.laterals_at.resize(n);
  for (std::size_t a = 0; a < layout.axes.size(); ++a) {
    const NodeId p = tree.parent(layout.axes[a].front());
    if (p != kNoNode && layout.nearest[p] != kNoNode)
      layout.laterals_at[layout.nearest[p]].push_back(a);
  }
  return layout;
}

// Meshes the axes one after the other, root axis first, so that every lateral finds the hole its
// parent left open and the frame at its parent's tip.
class ContinuousMesher {
 public:
  ContinuousMesher(const TreeGraph& tree, const MeshOptions& options)
      : tree_(tree),
        options_(options),
        layout_(layout_axes(tree, options.max_birth_time)),
        builder_(tree, layout_.reference_time),
        holes_(layout_.axes.size()),
        tip_v_(tree.size()),
        tip_t_(tree.size()),
        has_tip_(tree.size(), 0),
        width_at_node_(tree.size(), 0.0) {}

  TriangleMesh mesh() {
    for (std::size_t a = 0; a < layout_.axes.size(); ++a) mesh_axis(a);
    return builder_.finish();
  }

 private:
  // One axis: its rings, their frames and vertices, the holes its laterals leave through, the
  // walls between the rings, and its two ends.
  void mesh_axis(std::size_t a) {
    std::vector<NodeId> segs;
    for (NodeId id : layout_.axes[a]) {
      if (seg(tree_, id).norm() > kMinSegmentM) segs.push_back(id);
    }
    if (segs.empty()) return;
    const NodeId first_parent = tree_.parent(layout_.axes[a].front());
    attach_ = first_parent == kNoNode ? kNoNode : layout_.nearest[first_parent];
    set_width_profile(segs);
    const double distance =
        options_.camera_m ? (tree_.start(segs[0]) - *options_.camera_m).norm() : 0.0;
    const int s = sides_for_radius(radius_at(segs[0], 0.0), options_, distance);

    std::vector<Ring> rings = axis_rings(segs);
    width_at_node_[segs.back()] = rings.back().radius;
    if (holes_[a].valid && holes_[a].collar_m > 0.0) add_collar_ring(holes_[a], segs[0], rings);
    frame_rings(a, segs.back(), rings);
    const bool from_hole = holes_[a].valid;  // ring 0 is then the parent's open quad
    const std::vector<std::uint32_t> first = ring_vertices(rings, s, from_hole);
    const std::vector<std::vector<int>> open_quads = open_lateral_holes(rings, first, s);
    walls(first, open_quads, s, from_hole);
    if (from_hole) zip_onto_hole(holes_[a], segs[0], rings, first[1], s);
    caps(rings, first, s, from_hole);
  }

  // Reynolds expression 1 from the width where the axis leaves its parent, or the tree's radii.
  void set_width_profile(const std::vector<NodeId>& segs) {
    total_m_ = 0.0;
    for (NodeId id : segs) total_m_ += seg(tree_, id).norm();
    root_width_ = options_.reynolds_width && attach_ != kNoNode && width_at_node_[attach_] > 0
                      ? width_at_node_[attach_]
                      : tree_.radius(segs[0]);
  }

  double radius_at(NodeId node, double along) const {
    const double r = options_.reynolds_width ? root_width_ * reynolds_width(along / total_m_)
                                             : tree_.radius(node);
    return std::max(r, options_.min_radius_m);
  }

  // Rings at the joints (bisector tangents), plus a knuckle ring above every joint that
  // laterals leave from, at the lateral's width (Reynolds: "two rings ... separated by the
  // width of the branch").
  std::vector<Ring> axis_rings(const std::vector<NodeId>& segs) {
    const std::size_t m = segs.size();
    std::vector<Ring> rings;
    double along = 0.0;
    for (std::size_t j = 0; j <= m; ++j) {
      Ring r;
      const NodeId below = j > 0 ? segs[j - 1] : segs[0];
      const NodeId above = j < m ? segs[j] : segs[m - 1];
      r.center = j < m ? tree_.start(above) : tree_.end(below);
      const Eigen::Vector3d tb = seg(tree_, below).normalized(),
                            ta = seg(tree_, above).normalized();
      r.tangent = (tb + ta).norm() > 1e-9 ? (tb + ta).normalized() : ta;
      r.along = along;
      r.node = j < m ? above : below;
      r.bone0 = below;
      r.bone1 = above;
      r.radius = radius_at(r.node, along);
      width_at_node_[below] = r.radius;
      rings.push_back(r);
      if (j > 0 && j < m && !layout_.laterals_at[below].empty()) {
        rings.back().laterals = layout_.laterals_at[below];
        rings.push_back(knuckle_ring(r, layout_.laterals_at[below], above, ta, along));
      }
      if (j < m) along += seg(tree_, above).norm();
    }
    return rings;
  }

  // The knuckle is as tall as the lateral is wide, and twice the height at which the lateral's
  // axis leaves the parent's surface, so that axis runs through the open quad.
  Ring knuckle_ring(const Ring& r, const std::vector<std::size_t>& laterals, NodeId above,
                    const Eigen::Vector3d& ta, double along) const {
    double h = 0.0;
    for (std::size_t c : laterals) {
      const NodeId c0 = layout_.axes[c].front();
      const double cos_t = std::clamp(seg(tree_, c0).normalized().dot(ta), -1.0, 1.0);
      const double sin_t = std::sqrt(1.0 - cos_t * cos_t);
      const double exit = sin_t > 1e-6 ? r.radius * std::max(cos_t, 0.0) / sin_t : 1e9;
      h = std::max({h, 2.0 * tree_.radius(c0), 2.0 * exit});
    }
    const double len = seg(tree_, above).norm();
    h = std::min(std::max(h, 0.05 * len), 0.5 * len);
    Ring k = r;
    k.center = r.center + h * ta;
    k.tangent = ta;
    k.along = along + h;
    k.node = above;
    k.bone0 = k.bone1 = above;
    k.radius = radius_at(above, along + h);
    return k;
  }

  // A lateral's first own ring, just outside its parent's surface.
  void add_collar_ring(const Hole& hole, NodeId first_seg, std::vector<Ring>& rings) const {
    Ring c = rings[0];
    const Eigen::Vector3d t0 = seg(tree_, first_seg).normalized();
    c.center = rings[0].center + hole.collar_m * t0;
    c.tangent = t0;
    c.along = hole.collar_m;
    c.bone0 = c.bone1 = first_seg;
    c.radius = radius_at(first_seg, c.along);
    rings.insert(rings.begin() + 1, c);
  }

  // Ring frames by parallel transport from the hole's frame, the parent's tip frame, or any.
  void frame_rings(std::size_t a, NodeId last_seg, std::vector<Ring>& rings) {
    std::vector<Eigen::Vector3d> tangents;
    for (const Ring& r : rings) tangents.push_back(r.tangent);
    Eigen::Vector3d v0 = any_perpendicular(tangents[0]);
    if (holes_[a].valid) {
      v0 = holes_[a].v0;
    } else if (attach_ != kNoNode && has_tip_[attach_]) {
      v0 = transport(tip_v_[attach_], tip_t_[attach_], tangents[0]);
    }
    const std::vector<Eigen::Vector3d> vs = parallel_transport_normals(tangents, v0);
    for (std::size_t i = 0; i < rings.size(); ++i) rings[i].v = vs[i];
    tip_v_[last_seg] = vs.back();
    tip_t_[last_seg] = tangents.back();
    has_tip_[last_seg] = 1;
  }

  // Ring vertices (s + 1 with the seam repeated); the first vertex of each ring.
  std::vector<std::uint32_t> ring_vertices(const std::vector<Ring>& rings, int s, bool from_hole) {
    const double v_scale = 1.0 / (kTwoPi * std::max(rings[0].radius, options_.min_radius_m));
    std::vector<std::uint32_t> first(rings.size());
    for (std::size_t i = from_hole ? 1 : 0; i < rings.size(); ++i) {
      const Ring& r = rings[i];
      const Eigen::Vector3d w = r.tangent.cross(r.v);
      for (int k = 0; k < s; ++k) {
        const double ang = kTwoPi * k / s;
        const Eigen::Vector3d dir = std::cos(ang) * r.v + std::sin(ang) * w;
        const std::uint32_t id =
            builder_.vertex(r.center + r.radius * dir, dir, static_cast<float>(k) / s,
                            static_cast<float>(r.along * v_scale), r.node, r.bone0, r.bone1);
        if (k == 0) first[i] = id;
      }
      // The seam: the first vertex again with u = 1, the same point of the surface.
      builder_.copy(first[i], r.v, 1.0f, static_cast<float>(r.along * v_scale), r.node);
    }
    return first;
  }

  // Holes for laterals, decided before the walls so their quads are left open: per ring, the
  // quads above it that laterals leave through.
  std::vector<std::vector<int>> open_lateral_holes(const std::vector<Ring>& rings,
                                                   const std::vector<std::uint32_t>& first, int s) {
    std::vector<std::vector<int>> open_quads(rings.size());
    for (std::size_t i = 0; i + 1 < rings.size(); ++i) {
      for (std::size_t c : rings[i].laterals) {
        const NodeId c0 = layout_.axes[c].front();
        if (seg(tree_, c0).norm() <= kMinSegmentM) continue;
        const Ring& r = rings[i];
        const Eigen::Vector3d tc = seg(tree_, c0).normalized();
        const Eigen::Vector3d w = r.tangent.cross(r.v);
        double phi = std::atan2(tc.dot(w), tc.dot(r.v));
        if (phi < 0) phi += kTwoPi;
        const int k = std::min(static_cast<int>(phi / (kTwoPi / s)), s - 1);
        auto& taken = open_quads[i];
        if (std::find(taken.begin(), taken.end(), k) != taken.end()) continue;
        Hole h;
        h.vertices = {first[i] + k, first[i] + k + 1, first[i + 1] + k + 1, first[i + 1] + k};
        h.v0 = transport(r.v, r.tangent, tc);
        if (!lateral_leaves_outwards(r, c0, tc, h)) continue;
        taken.push_back(k);
        h.valid = true;
        holes_[c] = h;
      }
    }
    return open_quads;
  }

  // The lateral must leave the hole outwards: its first ring beyond the hole, and the hole
  // corners all around its axis (each angular gap below pi). Sets the hole's collar.
  bool lateral_leaves_outwards(const Ring& r, NodeId c0, const Eigen::Vector3d& tc, Hole& h) const {
    const Eigen::Vector3d origin = tree_.start(c0);
    const Eigen::Vector3d hw = tc.cross(h.v0);
    std::array<double, 4> ang{};
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int q = 0; q < 4; ++q) {
      const Eigen::Vector3d p = builder_.position(h.vertices[q]).cast<double>();
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
    const double collar = (sin_t > 1e-6 ? r.radius / sin_t : 1e9) + tree_.radius(c0);
    const double c0_len = seg(tree_, c0).norm();
    h.collar_m = collar < 0.6 * c0_len ? collar : 0.0;
    const double beyond =
        (origin + (h.collar_m > 0.0 ? h.collar_m : c0_len) * tc - centroid).dot(tc);
    return max_gap < M_PI - 1e-3 && beyond > 0.2 * tree_.radius(c0);
  }

  // Walls: (a, b, d) and (a, d, c) face outwards, as in the chain mesher.
  void walls(const std::vector<std::uint32_t>& first,
             const std::vector<std::vector<int>>& open_quads, int s, bool from_hole) {
    for (std::size_t i = from_hole ? 1 : 0; i + 1 < first.size(); ++i) {
      for (int k = 0; k < s; ++k) {
        if (std::find(open_quads[i].begin(), open_quads[i].end(), k) != open_quads[i].end()) {
          continue;
        }
        const std::uint32_t p = first[i] + k, q = p + 1, r = first[i + 1] + k, t = r + 1;
        builder_.triangle(p, q, t);
        builder_.triangle(p, t, r);
      }
    }
  }

  // The lateral's base zipped onto the parent's hole.
  void zip_onto_hole(const Hole& h, NodeId first_seg, const std::vector<Ring>& rings,
                     std::uint32_t upper0, int s) {
    const Eigen::Vector3d origin = tree_.start(first_seg);
    const Eigen::Vector3d& t0 = rings[0].tangent;
    const Eigen::Vector3d& v0 = rings[0].v;
    const Eigen::Vector3d hw = t0.cross(v0);
    std::array<std::pair<double, std::uint32_t>, 4> hv;
    for (int q = 0; q < 4; ++q) {
      const Eigen::Vector3d p = builder_.position(h.vertices[q]).cast<double>();
      const Eigen::Vector3d d = p - origin;
      double ang = std::atan2(d.dot(hw), d.dot(v0));
      if (ang < 0) ang += kTwoPi;
      // The hole's corners again, at the same positions, with normals radial to the lateral
      // (the parent's radial normals would shade the collar as if it faced the trunk).
      const Eigen::Vector3d radial = d - d.dot(t0) * t0;
      builder_.add_influence(h.vertices[q], first_seg, 1.0f);
      hv[q] = {ang, builder_.copy(h.vertices[q], radial, static_cast<float>(ang / kTwoPi), 0.0f,
                                  first_seg)};
    }
    std::sort(hv.begin(), hv.end());
    // Hole loop h0..h3 then h0 again at +2 pi; ring 1 loop 0..s (seam at 2 pi). Advance on
    // whichever loop has the smaller next angle (lower loop = hole, upper = ring 1).
    std::vector<std::pair<double, std::uint32_t>> lower(hv.begin(), hv.end());
    lower.push_back({hv[0].first + kTwoPi, hv[0].second});
    std::size_t i = 0, j = 0;
    while (i + 1 < lower.size() || j < static_cast<std::size_t>(s)) {
      const double next_upper = kTwoPi * static_cast<double>(j + 1) / s;
      const bool take_upper = j < static_cast<std::size_t>(s) &&
                              (i + 1 >= lower.size() || next_upper <= lower[i + 1].first);
      if (take_upper) {
        builder_.triangle(lower[i].second, upper0 + static_cast<std::uint32_t>(j + 1),
                          upper0 + static_cast<std::uint32_t>(j));
        ++j;
      } else {
        builder_.triangle(lower[i].second, lower[i + 1].second,
                          upper0 + static_cast<std::uint32_t>(j));
        ++i;
      }
    }
  }

  // Caps at the tip, and at the base unless it was zipped onto a hole.
  void caps(const std::vector<Ring>& rings, const std::vector<std::uint32_t>& first, int s,
            bool from_hole) {
    for (int end = from_hole ? 1 : 0; end < 2; ++end) {
      const std::size_t ri = end == 0 ? 0 : rings.size() - 1;
      const Ring& r = rings[ri];
      const Eigen::Vector3d nrm = end == 0 ? -r.tangent : r.tangent;
      const std::uint32_t hub =
          builder_.vertex(r.center, nrm, 0.5f, 0.5f, r.node, r.bone0, r.bone1);
      for (int k = 0; k < s; ++k) builder_.copy(first[ri] + k, nrm, 0.5f, 0.5f, r.node);
      for (int k = 0; k < s; ++k) {
        const std::uint32_t p = hub + 1 + k, q = hub + 1 + (k + 1) % s;
        if (end == 0) {
          builder_.triangle(hub, q, p);
        } else {
          builder_.triangle(hub, p, q);
        }
      }
    }
  }

  const TreeGraph& tree_;
  const MeshOptions& options_;
  AxisLayout layout_;
  Builder builder_;
  std::vector<Hole> holes_;  // by axis: the hole it leaves its parent through
  std::vector<Eigen::Vector3d> tip_v_, tip_t_;
  std::vector<char> has_tip_;
  std::vector<double> width_at_node_;
  // The axis being meshed.
  NodeId attach_ = kNoNode;
  double total_m_ = 0.0;
  double root_width_ = 0.0;
};

}  // namespace

TriangleMesh mesh_tree_continuous(const TreeGraph& tree, const MeshOptions& options) {
  MeshOptions leaves_only = options;
  leaves_only.junctions = JunctionMode::kSeparate;
  leaves_only.bark = false;
  leaves_only.leaf_bones = true;
  TriangleMesh leaves = mesh_tree(tree, leaves_only);  // validates the options too
  if (tree.size() == 0 || !options.bark) return leaves;
  TriangleMesh bark = ContinuousMesher(tree, options).mesh();
  bark.append(leaves);
  return bark;
}

}  // namespace fspm::graphics
