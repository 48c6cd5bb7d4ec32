#include "greenlab/expand.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "fspm/attribute_names.hpp"
#include "fspm/error.hpp"
#include "fspm/instanced_ctree.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/saturating.hpp"

namespace fspm::greenlab {
namespace {

// No prototype yet for this axis start (reconstruct_instanced, the line tree's instancing).
constexpr std::uint32_t kNoPrototype = 0xFFFFFFFFu;

constexpr double kDegToRad = std::numbers::pi / 180.0;

std::string age_key(int p, const char* name) { return "age." + std::to_string(p) + "." + name; }

// Local frame of a turtle: columns heading, left, up (heading x left = up).
struct Frame {
  Eigen::Matrix3d axes;
  Eigen::Vector3d position;
};

// Per-age rotations precomputed once: phyllotaxy about the heading, branching towards the left.
struct AgeRotations {
  Eigen::Matrix3d phyllotaxy;
  Eigen::Matrix3d branching;
};

// axes * phyllotaxy for a rotation about the heading (x): the heading stays, the two other
// columns turn. The skipped products are exact zeros (x * 0 added to a sum), so this equals the
// full 3x3 product bit for bit, at 12 multiplications instead of 27.
void turn_about_heading(Eigen::Matrix3d& axes, const Eigen::Matrix3d& r) {
  const Eigen::Vector3d c1 = axes.col(1) * r(1, 1) + axes.col(2) * r(2, 1);
  const Eigen::Vector3d c2 = axes.col(1) * r(1, 2) + axes.col(2) * r(2, 2);
  axes.col(1) = c1;
  axes.col(2) = c2;
}

bool is_rotation_about_x(const Eigen::Matrix3d& r) {
  return r(0, 0) == 1.0 && r(0, 1) == 0.0 && r(0, 2) == 0.0 && r(1, 0) == 0.0 && r(2, 0) == 0.0;
}

// Reconstruction always gives length and unit direction; add_node_unchecked skips deriving them
// (and the checks). A negative length from a hand-made file keeps add_node's behaviour.
NodeId add_to(TreeGraph& tree, NodeId parent, const NodeData& node) {
  return node.length >= 0.0 ? tree.add_node_unchecked(parent, node) : tree.add_node(parent, node);
}

Eigen::Matrix3d plagiotropic_frame(const Eigen::Vector3d& heading, const Eigen::Vector3d& left) {
  // Massart: lateral axes lie in the horizontal plane, whatever their insertion.
  Eigen::Vector3d h(heading.x(), heading.y(), 0.0);
  if (h.squaredNorm() < 1e-12) h = Eigen::Vector3d(left.x(), left.y(), 0.0);
  if (h.squaredNorm() < 1e-12) h = Eigen::Vector3d::UnitX();
  h.normalize();
  const Eigen::Vector3d u = Eigen::Vector3d::UnitZ();
  Eigen::Matrix3d m;
  m.col(0) = h;
  m.col(1) = u.cross(h);
  m.col(2) = u;
  return m;
}

}  // namespace

const AgeGeometry& ReconstructionParams::age(int p) const {
  static const AgeGeometry kDefault{};
  if (p < 1 || static_cast<std::size_t>(p) > ages.size()) return kDefault;
  return ages[static_cast<std::size_t>(p - 1)];
}

namespace {

// The metadata key of each number of AgeGeometry: one table for writing and reading. The keys of
// the last three are written only when they differ from the default, so that plants without them
// keep their files byte for byte.
struct GeometryField {
  const char* key;
  double AgeGeometry::*member;
  bool written_when_default;
};
constexpr GeometryField kGeometryFields[] = {
    {"leaf_life_span", &AgeGeometry::leaf_life_span, true},
    {"axis_life_span", &AgeGeometry::axis_life_span, true},
    {"pruning_period", &AgeGeometry::pruning_period, true},
    {"branching_angle_deg", &AgeGeometry::branching_angle_deg, true},
    {"phyllotaxy_deg", &AgeGeometry::phyllotaxy_deg, true},
    {"straightening", &AgeGeometry::straightening, true},
    {"internode_length_m", &AgeGeometry::internode_length_m, true},
    {"internode_radius_m", &AgeGeometry::internode_radius_m, true},
    {"radius_growth_m", &AgeGeometry::radius_growth_m, true},
    {"leaf_length_m", &AgeGeometry::leaf_length_m, true},
    {"leaf_angle_increase_deg", &AgeGeometry::leaf_angle_increase_deg, false},
    {"leaf_opening", &AgeGeometry::leaf_opening_cycles, false},
};

}  // namespace

std::map<std::string, double> geometry_metadata(const PlantParams& params) {
  std::map<std::string, double> m;
  m["age.count"] = static_cast<double>(params.ages.size());
  const AgeGeometry kDefault{};
  for (const auto& a : params.ages) {
    const int p = a.index;
    const AgeGeometry& g = a.geometry;
    for (const GeometryField& f : kGeometryFields) {
      if (f.written_when_default || g.*f.member != kDefault.*f.member) {
        m[age_key(p, f.key)] = g.*f.member;
      }
    }
    m[age_key(p, "plagiotropic")] = g.plagiotropic() ? 1.0 : 0.0;
    if (g.leaf_on_surface) m[age_key(p, "leaf_on_surface")] = 1.0;
  }
  const auto& f = params.functional;
  m["functional.enabled"] = f.enabled ? 1.0 : 0.0;
  m["functional.leaf_thickness"] = f.leaf_thickness;
  m["functional.reference_length"] = f.reference_length;
  m["functional.allometry_b"] = f.allometry_b;
  return m;
}

ReconstructionParams ReconstructionParams::from_metadata(const std::map<std::string, double>& m) {
  ReconstructionParams r;
  auto get = [&](const std::string& key, double fallback) {
    const auto it = m.find(key);
    return it == m.end() ? fallback : it->second;
  };
  const double count = get("age.count", 0.0);
  if (!(count >= 0.0 && count <= 65535.0)) throw ValueError("invalid age.count in graph metadata");
  r.ages.resize(static_cast<std::size_t>(count));
  for (int p = 1; p <= static_cast<int>(r.ages.size()); ++p) {
    AgeGeometry& a = r.ages[static_cast<std::size_t>(p - 1)];
    for (const GeometryField& f : kGeometryFields)
      a.*f.member = get(age_key(p, f.key), a.*f.member);
    a.orientation = get(age_key(p, "plagiotropic"), 0.0) != 0.0 ? Orientation::kPlagiotropic
                                                                : Orientation::kOrthotropic;
    a.leaf_on_surface = get(age_key(p, "leaf_on_surface"), 0.0) != 0.0;
  }
  r.from_volumes = get("functional.enabled", 0.0) != 0.0;
  r.leaf_thickness = get("functional.leaf_thickness", r.leaf_thickness);
  r.reference_length = get("functional.reference_length", r.reference_length);
  r.allometry_b = get("functional.allometry_b", r.allometry_b);
  return r;
}

double leaf_insertion_angle_deg(double branching_deg, double increase_deg, double opening_cycles,
                                double leaf_age_cycles) {
  double eased = 1.0;
  if (opening_cycles > 0.0) {
    const double x = std::clamp(leaf_age_cycles / opening_cycles, 0.0, 1.0);
    eased = x * x * (3.0 - 2.0 * x);
  }
  return branching_deg + increase_deg * eased;
}

InternodeDimensions internode_dimensions(double pith_volume, double ring_volume,
                                         double reference_length, double allometry_b) {
  InternodeDimensions d;
  if (pith_volume <= 0.0) return d;
  const double v_ref = std::numbers::pi * reference_length;  // annex: V_ref = pi H_ref
  const double ratio = pith_volume / v_ref;
  const double b = allometry_b;
  d.length = reference_length * std::pow(ratio, b / (1.0 + b));
  const double rp2 =
      v_ref / (std::numbers::pi * reference_length) * std::pow(ratio, 1.0 / (1.0 + b));
  d.pith_radius = std::sqrt(rp2);
  d.radius = std::sqrt(rp2 + std::max(ring_volume, 0.0) / (std::numbers::pi * d.length));
  return d;
}

namespace {

struct AxisStart {
  RecordId record;
  NodeId parent;
  Frame frame;
  std::uint16_t order;
};

// Walks axes of a compressed graph into explicit nodes; shared by the explicit and the instanced
// reconstruction.
class AxisBuilder {
 public:
  AxisBuilder(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
              bool absolute_effects)
      : graph_(graph),
        geo_(ReconstructionParams::from_metadata(graph.metadata)),
        options_(options),
        absolute_effects_(absolute_effects) {
    final_age_ = graph.final_age;
    age_ = options.age < 0.0 ? final_age_ : options.age;
    if (age_ > final_age_ + 1e-9) {
      throw ValueError("cannot reconstruct at age " + std::to_string(age_) +
                       ": the graph was simulated to age " + std::to_string(final_age_));
    }
    now_ = graph.birth_date + age_;
    final_date_ = graph.birth_date + final_age_;
    n_ages_ = std::max<std::size_t>(geo_.ages.size(), 1);
    rot_.resize(n_ages_ + 1);
    for (std::size_t p = 1; p <= n_ages_; ++p) {
      const AgeGeometry& a = geo_.age(static_cast<int>(p));
      rot_[p].phyllotaxy = Eigen::AngleAxisd(a.phyllotaxy_deg * kDegToRad, Eigen::Vector3d::UnitX())
                               .toRotationMatrix();
      rot_[p].branching =
          Eigen::AngleAxisd(a.branching_angle_deg * kDegToRad, Eigen::Vector3d::UnitZ())
              .toRotationMatrix();
      any_pruning_period_ = any_pruning_period_ || a.pruning_period > 0.0;
      phyllotaxy_about_heading_ =
          phyllotaxy_about_heading_ && is_rotation_about_x(rot_[p].phyllotaxy);
    }
  }

  double age() const { return age_; }
  double now() const { return now_; }
  // Whether axes of physiological age p depend on their absolute orientation (straightening of
  // orthotropic axes, plagiotropic flattening), so that their instances differ by more than a
  // rigid placement.
  bool orientation_dependent(int p) const {
    const AgeGeometry& g = geo_.age(p);
    return g.plagiotropic() || g.straightening > 0.0;
  }
  bool any_pruning_period() const { return any_pruning_period_; }

  Frame trunk_frame() const {
    Frame trunk;
    trunk.axes.col(0) = Eigen::Vector3d::UnitZ();
    trunk.axes.col(1) = Eigen::Vector3d::UnitY();
    trunk.axes.col(2) = Eigen::Vector3d::UnitZ().cross(Eigen::Vector3d::UnitY());
    trunk.position.setZero();
    return trunk;
  }

  Frame root_frame() const {
    Frame f = trunk_frame();
    if (absolute_effects_ &&
        geo_.age(graph_.record(graph_.root()).physiological_age).plagiotropic()) {
      f.axes = plagiotropic_frame(Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY());
    }
    return f;
  }

  // Jaeger 3.2.1, sign arranged so that a positive status means present:
  // status = organ birth + life span + pruning period - present date; > pruning period: alive,
  // in (0, pruning period]: dead but still on the plant, <= 0: pruned.
  double status(double birth, double span, double pruning) const {
    return span <= 0.0 ? std::numeric_limits<double>::infinity() : birth + span + pruning - now_;
  }

  // Records a metamer instance of `r` adds at most (pruned axes aside): its internode, its leaf
  // while present, its terminal flower.
  std::uint64_t records_per_metamer(const CompressedRecord& r) const {
    const AgeGeometry& g = geo_.age(r.physiological_age);
    const bool leaf = options_.leaves && status(r.birth, g.leaf_life_span, g.pruning_period) > 0.0;
    const bool flower = options_.flowers && r.apex == ApexState::kFlower;
    return 1 + (leaf ? 1 : 0) + (flower ? 1 : 0);
  }

  // Whether a lateral axis starting at `record` has fallen (Jaeger 3.2.1 applied to axes).
  bool pruned(RecordId record) const {
    const CompressedRecord& r = graph_.record(record);
    const AgeGeometry& g = geo_.age(r.physiological_age);
    return status(r.birth, g.axis_life_span, g.pruning_period) <= 0.0;
  }

  // Adds the axis starting at axis.record under axis.parent; its laterals go to `laterals`.
  // Metamer by metamer: the internode, its leaf and its laterals at its top, then the frame
  // turned for the next metamer; the terminal flower after the last one. `node` is one record
  // reused for every organ, so an organ keeps the fields of the internode it does not set.
  void walk(const AxisStart& axis, TreeGraph& tree, std::vector<AxisStart>& laterals,
            ReconstructionStats& st) const {
    const bool axis_dead = lateral_axis_dead(axis.record);
    Frame f = axis.frame;
    NodeId parent = axis.parent;
    RecordId id = axis.record;
    NodeData node;
    while (true) {
      const CompressedRecord& r = graph_.record(id);
      const AgeGeometry& g = geo_.age(r.physiological_age);
      const AgeRotations& rp = rotations(r.physiological_age);
      const NodeId internode = add_internode(r, g, axis.order, f, parent, tree, node);
      ++st.metamers;
      if (axis_dead && any_pruning_period_) tree.attribute(kDeadAttribute)[internode] = 1.0;
      // The leaf and the laterals sit at the top of the metamer, their azimuth set by phyllotaxy.
      if (options_.leaves) add_leaf(r, g, rp, axis.order, f, internode, tree, node, st);
      queue_laterals(id, axis.order, f, internode, laterals, st);
      next_metamer_frame(g, rp, f);
      parent = internode;
      if (r.successor == kNoRecord || graph_.record(r.successor).birth > now_) {
        add_flower(r, g, axis.order, f, internode, tree, node, st);
        break;
      }
      id = r.successor;
    }
  }

  // Whether the lateral axis starting at `record` is dead but not yet fallen (Jaeger 3.2.1);
  // the root never starts a lateral.
  bool lateral_axis_dead(RecordId record) const {
    if (record == graph_.root()) return false;
    const CompressedRecord& r = graph_.record(record);
    const AgeGeometry& g = geo_.age(r.physiological_age);
    return status(r.birth, g.axis_life_span, g.pruning_period) <= g.pruning_period;
  }

  // The internode of metamer `r` along the heading of `f`, which it moves to its top. Its length
  // and radius are the parameters' or (GL1) from its volumes, the radius interpolated to the
  // present date.
  NodeId add_internode(const CompressedRecord& r, const AgeGeometry& g, std::uint16_t order,
                       Frame& f, NodeId parent, TreeGraph& tree, NodeData& node) const {
    double length = g.internode_length_m;
    double r_birth = g.internode_radius_m;
    double r_final = g.internode_radius_m + g.radius_growth_m * (final_date_ - r.birth);
    if (geo_.from_volumes) {
      const auto dim = internode_dimensions(r.pith_volume, r.ring_volume, geo_.reference_length,
                                            geo_.allometry_b);
      length = dim.length;
      r_birth = dim.pith_radius;
      r_final = dim.radius;
    }
    double radius = r_final;
    if (now_ < final_date_ && final_date_ > r.birth) {
      // Jaeger 3.2.2: quadratic interpolation of the diameter from birth to the final age.
      const double x = (now_ - r.birth) / (final_date_ - r.birth);
      radius = r_birth + (r_final - r_birth) * x * x;
    }
    const Eigen::Vector3d heading = f.axes.col(0);
    node.start = f.position;
    f.position += heading * length;
    node.end = f.position;
    node.direction = heading;
    node.length = length;
    node.radius = radius;
    node.birth_time = r.birth;
    node.physiological_age = static_cast<std::uint16_t>(r.physiological_age);
    node.order = order;
    node.kind = OrganKind::kInternode;
    return add_to(tree, parent, node);
  }

  // The leaf of metamer `r` while it is present (Jaeger 3.2.1), flagged dead in its pruning
  // period; `node` still holds the internode, whose radius places the leaf.
  void add_leaf(const CompressedRecord& r, const AgeGeometry& g, const AgeRotations& rp,
                std::uint16_t order, const Frame& f, NodeId internode, TreeGraph& tree,
                NodeData& node, ReconstructionStats& st) const {
    const double s = status(r.birth, g.leaf_life_span, g.pruning_period);
    if (s <= 0.0) return;
    double leaf_length = g.leaf_length_m;
    if (geo_.from_volumes) {
      leaf_length = std::sqrt(std::max(r.leaf_volume, 0.0) / geo_.leaf_thickness);
    }
    place_leaf(f, g, rp, node.radius, now_ - r.birth, node);
    node.end = node.start + node.direction * leaf_length;
    node.length = leaf_length;
    node.radius = 0.0;
    node.kind = OrganKind::kLeaf;
    node.order = static_cast<std::uint16_t>(order + 1);
    const NodeId leaf = add_to(tree, internode, node);
    ++st.leaves;
    if (any_pruning_period_ && s <= g.pruning_period) tree.attribute(kDeadAttribute)[leaf] = 1.0;
  }

  // The lateral axes born at the top of metamer `id`, spread evenly around the heading and
  // turned by their branching angle; fallen ones counted, those past the order limit skipped.
  void queue_laterals(RecordId id, std::uint16_t order, const Frame& f, NodeId internode,
                      std::vector<AxisStart>& laterals, ReconstructionStats& st) const {
    const auto ax = graph_.axillaries(id);
    if (ax.empty()) return;
    const double spread = 2.0 * std::numbers::pi / static_cast<double>(ax.size());
    for (std::size_t k = 0; k < ax.size(); ++k) {
      const CompressedRecord& child = graph_.record(ax[k]);
      if (child.birth > now_) continue;
      if (pruned(ax[k])) {
        ++st.pruned_axes;  // the whole lateral axis has fallen
        continue;
      }
      if (order + 1 > options_.lod.max_order) continue;  // Jaeger 3.1.1: order limit
      const int q = child.physiological_age;
      Frame lf;
      lf.position = f.position;
      if (k > 0) {
        lf.axes = f.axes *
                  Eigen::AngleAxisd(spread * static_cast<double>(k), Eigen::Vector3d::UnitX())
                      .toRotationMatrix() *
                  rotations(q).branching;
      } else {
        lf.axes = f.axes * rotations(q).branching;
      }
      if (absolute_effects_ && geo_.age(q).plagiotropic()) {
        lf.axes = plagiotropic_frame(lf.axes.col(0), lf.axes.col(1));
      }
      laterals.push_back({ax[k], internode, lf, static_cast<std::uint16_t>(order + 1)});
    }
  }

  // The frame of the next metamer: turned by the phyllotaxy and, for orthotropic axes with
  // straightening (Rauh), its heading turned up by a fraction.
  void next_metamer_frame(const AgeGeometry& g, const AgeRotations& rp, Frame& f) const {
    if (phyllotaxy_about_heading_) {
      turn_about_heading(f.axes, rp.phyllotaxy);
    } else {
      f.axes = f.axes * rp.phyllotaxy;
    }
    if (absolute_effects_ && g.straightening > 0.0 && !g.plagiotropic()) {
      const Eigen::Vector3d h = f.axes.col(0);
      const Eigen::Vector3d target = (h + g.straightening * (Eigen::Vector3d::UnitZ() - h));
      if (target.squaredNorm() > 1e-12) {
        f.axes =
            Eigen::Quaterniond::FromTwoVectors(h, target.normalized()).toRotationMatrix() * f.axes;
      }
    }
  }

  // Terminal flower of the axis's last metamer, shown from the cycle after its growth unit.
  void add_flower(const CompressedRecord& r, const AgeGeometry& g, std::uint16_t order,
                  const Frame& f, NodeId internode, TreeGraph& tree, NodeData& node,
                  ReconstructionStats& st) const {
    if (!options_.flowers || r.apex != ApexState::kFlower || r.birth + 1.0 > now_ + 1e-9) return;
    node.start = f.position;
    node.direction = f.axes.col(0);
    node.end = f.position + node.direction * (0.5 * g.leaf_length_m);
    node.length = 0.5 * g.leaf_length_m;
    node.radius = 0.0;
    node.kind = OrganKind::kFlower;
    node.order = order;
    node.birth_time = r.birth + 1.0;
    add_to(tree, internode, node);
    ++st.flowers;
  }

  // Start and direction of the leaf at the top of a metamer of frame f and radius `radius`:
  // along the branching direction from the centre line, or (Jaeger 3.1.3) at a larger angle and
  // from the axis surface, on the side the leaf leans to.
  static void place_leaf(const Frame& f, const AgeGeometry& g, const AgeRotations& rp,
                         double radius, double leaf_age, NodeData& node) {
    node.start = f.position;
    if (g.leaf_angle_increase_deg == 0.0) {
      node.direction = f.axes * rp.branching.col(0);  // heading of f.axes * branching
    } else {
      const double a =
          kDegToRad * leaf_insertion_angle_deg(g.branching_angle_deg, g.leaf_angle_increase_deg,
                                               g.leaf_opening_cycles, leaf_age);
      node.direction = f.axes.col(0) * std::cos(a) + f.axes.col(1) * std::sin(a);
    }
    if (g.leaf_on_surface) {
      // The radial direction of the leaf: its direction without the heading component.
      const Eigen::Vector3d h = f.axes.col(0);
      Eigen::Vector3d radial = node.direction - node.direction.dot(h) * h;
      radial = radial.squaredNorm() > 1e-24 ? radial.normalized() : Eigen::Vector3d(f.axes.col(1));
      node.start += radius * radial;
    }
  }

 private:
  const AgeRotations& rotations(int p) const {
    return rot_[static_cast<std::size_t>(std::clamp<int>(p, 1, static_cast<int>(n_ages_)))];
  }

  const CompressedTreeGraph& graph_;
  ReconstructionParams geo_;
  ReconstructionOptions options_;
  bool absolute_effects_;
  double final_age_ = 0.0, age_ = 0.0, now_ = 0.0, final_date_ = 0.0;
  std::size_t n_ages_ = 1;
  std::vector<AgeRotations> rot_;
  bool any_pruning_period_ = false;
  bool phyllotaxy_about_heading_ = true;
};

}  // namespace

namespace {

// Sum over the metamer instances born by `age` of weight(record), walking an axillary reference
// only where walk_axillary(record) says so: records are numbered parents first by the
// simulation, but any order is handled by a topological pass. Saturating sums: a count past
// 2^64 only needs to compare as huge.
template <class Weight, class WalkAxillary>
std::uint64_t instances_at_age(const CompressedTreeGraph& graph, double age, Weight weight,
                               WalkAxillary walk_axillary) {
  if (graph.root() == kNoRecord) return 0;
  const double now = graph.birth_date + age;
  std::vector<std::uint32_t> indegree(graph.size(), 0);
  for (const auto& r : graph.records()) {
    if (r.successor != kNoRecord) ++indegree[r.successor];
  }
  for (RecordId a : graph.axillary_refs()) ++indegree[a];
  std::vector<std::uint64_t> count(graph.size(), 0);
  std::vector<RecordId> order;
  order.reserve(graph.size());
  for (RecordId i = 0; i < graph.size(); ++i) {
    if (indegree[i] == 0) order.push_back(i);
  }
  count[graph.root()] = 1;
  std::uint64_t total = 0;
  for (std::size_t head = 0; head < order.size(); ++head) {
    const RecordId id = order[head];
    const CompressedRecord& r = graph.record(id);
    const std::uint64_t c = r.birth <= now ? count[id] : 0;
    total = add_saturating(total, multiply_saturating(c, weight(r)));
    auto visit = [&](RecordId child, std::uint64_t n) {
      count[child] = add_saturating(count[child], n);
      if (--indegree[child] == 0) order.push_back(child);
    };
    if (r.successor != kNoRecord) visit(r.successor, c);
    for (RecordId a : graph.axillaries(id)) visit(a, walk_axillary(a) ? c : 0);
  }
  return total;
}

template <class Weight>
std::uint64_t instances_at_age(const CompressedTreeGraph& graph, double age, Weight weight) {
  return instances_at_age(graph, age, weight, [](RecordId) { return true; });
}

}  // namespace

std::uint64_t metamers_at_age(const CompressedTreeGraph& graph, double age) {
  return instances_at_age(graph, age, [](const CompressedRecord&) { return std::uint64_t{1}; });
}

std::uint64_t metamers_within_order(const CompressedTreeGraph& graph, double age,
                                    double max_order) {
  // A chain of k laterals passes k + 1 distinct records of the acyclic graph, so orders past
  // the record count never occur; a table too large to hold falls back to the plain count.
  const double n = static_cast<double>(graph.size());
  if (!(max_order < n) || n * (max_order + 1.0) > 1e8 || graph.root() == kNoRecord) {
    return metamers_at_age(graph, age);
  }
  if (max_order < 0.0) return 0;
  const auto orders = static_cast<std::size_t>(max_order) + 1;
  const double now = graph.birth_date + age;
  std::vector<std::uint32_t> indegree(graph.size(), 0);
  for (const auto& r : graph.records()) {
    if (r.successor != kNoRecord) ++indegree[r.successor];
  }
  for (RecordId a : graph.axillary_refs()) ++indegree[a];
  // count[id * orders + o]: instances of record id on axes of order o.
  std::vector<std::uint64_t> count(graph.size() * orders, 0);
  std::vector<RecordId> order;
  for (RecordId i = 0; i < graph.size(); ++i) {
    if (indegree[i] == 0) order.push_back(i);
  }
  count[graph.root() * orders] = 1;
  std::uint64_t total = 0;
  for (std::size_t head = 0; head < order.size(); ++head) {
    const RecordId id = order[head];
    const CompressedRecord& r = graph.record(id);
    const bool born = r.birth <= now;
    for (std::size_t o = 0; o < orders; ++o) {
      const std::uint64_t c = born ? count[id * orders + o] : 0;
      total = add_saturating(total, c);
      if (r.successor != kNoRecord) {
        std::uint64_t& to = count[r.successor * orders + o];
        to = add_saturating(to, c);
      }
      if (o + 1 >= orders) continue;
      for (RecordId a : graph.axillaries(id)) {
        std::uint64_t& to = count[a * orders + o + 1];
        to = add_saturating(to, c);
      }
    }
    auto visit = [&](RecordId child) {
      if (--indegree[child] == 0) order.push_back(child);
    };
    if (r.successor != kNoRecord) visit(r.successor);
    for (RecordId a : graph.axillaries(id)) visit(a);
  }
  return total;
}

std::uint64_t line_records_at_age(const CompressedTreeGraph& graph,
                                  const ReconstructionOptions& options) {
  if (graph.has_geometry()) return geometry_organ_count(graph);
  const AxisBuilder builder(graph, options, true);
  if (graph.root() == kNoRecord) return 0;
  const ReconstructionParams geo = ReconstructionParams::from_metadata(graph.metadata);
  const double now = builder.now();
  // The walk's rules, per record instead of per instance: a metamer is written when born, its
  // leaf while its death status is positive, its terminal flower from the cycle after its unit;
  // a lateral axis is walked when born and not fallen.
  const auto weight = [&](const CompressedRecord& r) {
    const AgeGeometry& g = geo.age(r.physiological_age);
    const bool leaf =
        options.leaves && builder.status(r.birth, g.leaf_life_span, g.pruning_period) > 0.0;
    const bool flower =
        options.flowers && r.apex == ApexState::kFlower && r.birth + 1.0 <= now + 1e-9;
    return std::uint64_t{1} + (leaf ? 1 : 0) + (flower ? 1 : 0);
  };
  return instances_at_age(graph, builder.age(), weight,
                          [&](RecordId a) { return !builder.pruned(a); });
}

namespace {

bool nothing_born(const CompressedTreeGraph& graph, const AxisBuilder& builder) {
  return graph.root() == kNoRecord || graph.record(graph.root()).birth > builder.now();
}

// Metamers born by the builder's age; throws when an explicit tree of them is too big.
std::uint64_t explicit_metamers(const CompressedTreeGraph& graph, const AxisBuilder& builder,
                                const LevelOfDetail& lod = {}) {
  const std::uint64_t metamers = metamers_within_order(graph, builder.age(), lod.max_order);
  if (metamers > kMaxExplicitMetamers) {
    throw ValueError("the plant has " + count_text(metamers) + " metamers at age " +
                     std::to_string(builder.age()) + ", too many for an explicit tree (at most " +
                     std::to_string(kMaxExplicitMetamers) +
                     "); use an earlier age or the instanced reconstruction");
  }
  return metamers;
}

// Graphs with turtle geometry (.ctree version 2, drawn L-systems) carry their own geometry:
// they are expanded as drawn, filtered by birth date, leaves and flowers; GreenLab's per-age
// numbers, death and pruning do not apply.
CtreeInstancingOptions geometry_options(const CompressedTreeGraph& graph,
                                        const ReconstructionOptions& options, double& age) {
  age = options.age < 0.0 ? graph.final_age : options.age;
  if (age > graph.final_age + 1e-9) {
    throw ValueError("cannot reconstruct at age " + std::to_string(age) +
                     ": the graph was simulated to age " + std::to_string(graph.final_age));
  }
  CtreeInstancingOptions o;
  o.max_birth = graph.birth_date + age;
  o.leaves = options.leaves;
  o.flowers = options.flowers;
  return o;
}

// Internodes, leaves and flowers of a tree written by a level of detail (merged internodes once).
void count_kinds(const TreeGraph& tree, ReconstructionStats& st) {
  st.metamers = st.leaves = st.flowers = 0;
  for (const OrganKind k : tree.kinds()) {
    st.metamers += k == OrganKind::kInternode ? 1 : 0;
    st.leaves += k == OrganKind::kLeaf ? 1 : 0;
    st.flowers += k == OrganKind::kFlower ? 1 : 0;
  }
}

TreeGraph reconstruct_geometry(const CompressedTreeGraph& graph,
                               const ReconstructionOptions& options, ReconstructionStats& st) {
  const CtreeInstancingOptions o = geometry_options(graph, options, st.age);
  const bool lod = options.lod.active();
  // With a level of detail the organs are counted on the reduced substructures.
  InstancedTree instanced;
  std::uint64_t organs = geometry_organ_count(graph);
  if (lod) {
    instanced = reduce_instanced_tree(instanced_tree_of(graph, o), options.lod);
    organs = count_instanced_tree(instanced).nodes;
  }
  if (organs > kMaxExplicitMetamers) {
    throw ValueError("the plant has " + count_text(organs) + " organs" +
                     (lod ? " at this level of detail" : "") +
                     ", too many for an explicit tree (at most " +
                     std::to_string(kMaxExplicitMetamers) +
                     "); use the instanced reconstruction or a lower maximum order");
  }
  if (!lod) instanced = instanced_tree_of(graph, o);
  TreeGraph tree = expand_instanced_tree(instanced, static_cast<std::size_t>(kMaxExplicitMetamers));
  count_kinds(tree, st);
  return tree;
}

}  // namespace

TreeGraph reconstruct(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                      ReconstructionStats* stats) {
  TreeGraph tree;
  reconstruct_into(graph, options, tree, stats);
  return tree;
}

void reconstruct_into(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                      TreeGraph& tree, ReconstructionStats* stats) {
  if (graph.has_geometry()) {
    ReconstructionStats st;
    tree = reconstruct_geometry(graph, options, st);
    if (stats) *stats = st;
    return;
  }
  const AxisBuilder builder(graph, options, true);
  ReconstructionStats st;
  st.age = builder.age();
  tree.clear_keep_capacity();
  if (nothing_born(graph, builder)) {
    if (stats) *stats = st;
    return;
  }
  // Metamers born by the requested age bound the output (each adds at most a leaf and a
  // flower), so the columns are allocated once and impossible requests fail early.
  const std::uint64_t bound = explicit_metamers(graph, builder, options.lod);
  if (builder.any_pruning_period()) tree.add_attribute(kDeadAttribute, 0.0);
  check_memory(
      static_cast<double>(bound * 2 + 8) * TreeGraph::bytes_per_node(tree.attribute_names().size()),
      "the explicit tree of " + std::to_string(bound) + " metamers");
  tree.reserve(static_cast<std::size_t>(bound * 2 + 8));
  tree.advise_huge_pages();
  // Oldest node first, axis by axis (Jaeger 3.1.1): a FIFO of axis starts.
  std::vector<AxisStart> queue{{graph.root(), kNoNode, builder.root_frame(), 0}};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const AxisStart axis = queue[head];  // copied: walk() appends to the queue
    builder.walk(axis, tree, queue, st);
  }
  if (options.lod.active()) {
    tree = reduce_tree(tree, options.lod);
    count_kinds(tree, st);
  }
  if (stats) *stats = st;
}

InstancedTree reconstruct_instanced(const CompressedTreeGraph& graph,
                                    const ReconstructionOptions& options) {
  if (graph.has_geometry()) {
    // Turtle geometry: the groups of the graph are the prototypes.
    double age = 0.0;
    return instanced_tree_of(graph, geometry_options(graph, options, age));
  }
  const AxisBuilder builder(graph, options, false);
  InstancedTree tree;
  if (nothing_born(graph, builder)) return tree;
  const Frame canonical = builder.trunk_frame();
  const Eigen::Matrix3d canonical_inverse = canonical.axes.transpose();
  std::vector<std::uint32_t> prototype_of(graph.size(), kNoPrototype);
  std::vector<RecordId> first_record{graph.root()};  // of each prototype's axis
  std::vector<AxisStart> laterals;
  // One prototype per axis start, built in its own frame; children placed by transforms.
  prototype_of[graph.root()] = 0;
  tree.prototypes.emplace_back();
  for (std::size_t i = 0; i < tree.prototypes.size(); ++i) {
    ReconstructionStats st;
    laterals.clear();
    TreeGraph geometry;
    if (builder.any_pruning_period()) geometry.add_attribute(kDeadAttribute, 0.0);
    builder.walk({first_record[i], kNoNode, canonical, 0}, geometry, laterals, st);
    std::vector<InstancedTree::Child> children;
    children.reserve(laterals.size());
    for (const AxisStart& l : laterals) {
      std::uint32_t& proto = prototype_of[l.record];
      if (proto == kNoPrototype) {
        proto = static_cast<std::uint32_t>(tree.prototypes.size());
        tree.prototypes.emplace_back();
        first_record.push_back(l.record);
      }
      children.push_back(
          {proto, l.parent, l.frame.axes * canonical_inverse, l.frame.position, 1.0});
    }
    InstancedTree::Prototype& p = tree.prototypes[i];
    p.geometry = std::move(geometry);
    p.children = std::move(children);
  }
  return tree;
}

namespace {

// Per record: whether it or anything it bears (successors, laterals, recursively) has an
// orientation-dependent physiological age. Reverse topological order over the DAG, so any record
// numbering is handled.
std::vector<std::uint8_t> orientation_dependent_below(const CompressedTreeGraph& graph,
                                                      const AxisBuilder& builder) {
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> indegree(n, 0);
  for (const auto& r : graph.records()) {
    if (r.successor != kNoRecord) ++indegree[r.successor];
  }
  for (RecordId a : graph.axillary_refs()) ++indegree[a];
  std::vector<RecordId> order;
  order.reserve(n);
  for (RecordId i = 0; i < n; ++i) {
    if (indegree[i] == 0) order.push_back(i);
  }
  for (std::size_t head = 0; head < order.size(); ++head) {
    const CompressedRecord& r = graph.record(order[head]);
    if (r.successor != kNoRecord && --indegree[r.successor] == 0) order.push_back(r.successor);
    for (RecordId a : graph.axillaries(order[head])) {
      if (--indegree[a] == 0) order.push_back(a);
    }
  }
  std::vector<std::uint8_t> dependent(n, 0);
  for (std::size_t k = order.size(); k-- > 0;) {
    const RecordId id = order[k];
    const CompressedRecord& r = graph.record(id);
    bool d = builder.orientation_dependent(r.physiological_age);
    if (!d && r.successor != kNoRecord) d = dependent[r.successor] != 0;
    for (RecordId a : graph.axillaries(id)) d = d || dependent[a] != 0;
    dependent[id] = d ? 1 : 0;
  }
  return dependent;
}

// Axes walked once in their own frame, stored in single precision one after the other.
class LinePrototypes {
 public:
  struct Child {
    RecordId record;
    NodeId attach;             // prototype-local node the lateral grows from
    Eigen::Matrix3f rotation;  // child frame -> prototype frame
    Eigen::Vector3f translation;
  };
  struct Prototype {
    std::uint32_t first = 0, count = 0;  // records in the pool
    std::uint32_t child_first = 0, child_count = 0;
    ReconstructionStats stats;
  };

  std::uint32_t index_of(RecordId record) const { return index_[record]; }
  void resize_index(std::size_t records) { index_.assign(records, kNoPrototype); }

  // Adds the prototype of `record` from an axis walked into `axis` (node 0 its base, frame
  // `canonical`) with its laterals.
  std::uint32_t add(RecordId record, const TreeGraph& axis, const std::vector<AxisStart>& laterals,
                    const Eigen::Matrix3d& canonical_inverse, const ReconstructionStats& st) {
    Prototype p;
    p.first = static_cast<std::uint32_t>(parent.size());
    p.count = static_cast<std::uint32_t>(axis.size());
    p.child_first = static_cast<std::uint32_t>(children.size());
    p.child_count = static_cast<std::uint32_t>(laterals.size());
    p.stats = st;
    const bool has_dead = axis.has_attribute(kDeadAttribute);
    for (NodeId k = 0; k < axis.size(); ++k) {
      parent.push_back(axis.parent(k));
      start.push_back(axis.start(k).cast<float>());
      direction.push_back(axis.direction(k).cast<float>());
      length.push_back(static_cast<float>(axis.length(k)));
      radius.push_back(static_cast<float>(axis.radius(k)));
      birth.push_back(static_cast<float>(axis.birth_time(k)));
      age.push_back(axis.physiological_age(k));
      order.push_back(axis.order(k));
      kind.push_back(axis.kind(k));
      dead.push_back(has_dead && axis.attribute(kDeadAttribute)[k] != 0.0 ? 1 : 0);
    }
    for (const AxisStart& l : laterals) {
      children.push_back({l.record, l.parent, (l.frame.axes * canonical_inverse).cast<float>(),
                          l.frame.position.cast<float>()});
    }
    prototypes.push_back(p);
    return index_[record] = static_cast<std::uint32_t>(prototypes.size() - 1);
  }

  std::vector<Prototype> prototypes;
  std::vector<Child> children;
  std::vector<NodeId> parent;
  std::vector<Eigen::Vector3f> start, direction;
  std::vector<float> length, radius, birth;
  std::vector<std::uint16_t> age, order;
  std::vector<OrganKind> kind;
  std::vector<std::uint8_t> dead;

 private:
  std::vector<std::uint32_t> index_;
};

void add_stats(ReconstructionStats& to, const ReconstructionStats& from) {
  to.metamers += from.metamers;
  to.leaves += from.leaves;
  to.flowers += from.flowers;
  to.pruned_axes += from.pruned_axes;
}

// One axis start waiting in the FIFO: a prototype placed by a single-precision rigid transform
// (most of them: 64 bytes each), or an axis to walk from its absolute frame (kept aside).
struct LineItem {
  RecordId record;
  NodeId parent;
  std::uint16_t order;
  std::uint32_t walk_frame;  // index into the walked frames, or kNoWalk for a prototype
  Eigen::Matrix3f rotation;
  Eigen::Vector3f translation;
};
constexpr std::uint32_t kNoWalk = 0xFFFFFFFFu;

// A prototype placed by the queue's item `item`, its records to be copied to [base, base + n).
struct PlacedCopy {
  std::uint32_t prototype;
  NodeId base;
  std::uint32_t item;
};

// Raw pointers to the columns of a line tree, taken again after each resize.
struct LineColumns {
  NodeId* parent = nullptr;
  Eigen::Vector3f *start = nullptr, *direction = nullptr;
  float *length = nullptr, *radius = nullptr, *birth = nullptr;
  std::uint16_t *age = nullptr, *order = nullptr;
  OrganKind* kind = nullptr;
  std::uint8_t* dead = nullptr;

  void bind(LineTree& lines) {
    parent = lines.parents().data();
    start = lines.starts().data();
    direction = lines.directions().data();
    length = lines.lengths().data();
    radius = lines.radii().data();
    birth = lines.birth_times().data();
    age = lines.physiological_ages().data();
    order = lines.orders().data();
    kind = lines.kinds().data();
    dead = lines.has_dead() ? lines.dead().data() : nullptr;
  }
};

// The records of every metamer born by the age with its leaf and flower bound the output (only
// fallen axes make it smaller): the columns are sized once, left unwritten, and cut to the
// records written at the end. Throws for plants too big for an explicit form.
void size_line_tree(const CompressedTreeGraph& graph, const AxisBuilder& builder, LineTree& lines) {
  explicit_metamers(graph, builder);
  const auto capacity = static_cast<std::size_t>(
      instances_at_age(graph, builder.age(),
                       [&](const CompressedRecord& r) { return builder.records_per_metamer(r); }));
  check_memory(static_cast<double>(capacity) * LineTree::kBytesPerRecord,
               "the explicit tree of " + std::to_string(capacity) + " records");
  if (lines.capacity() < capacity) {
    lines.reserve(capacity);
    lines.advise_huge_pages();
  }
  lines.resize_for_overwrite(capacity);
}

// Oldest node first, axis by axis (as reconstruct): a FIFO of axis starts. An axis whose subtree
// depends on its absolute orientation is walked from its frame and written at once; any other is
// a prototype walked once in the canonical frame, placed by a rigid transform, and copied after
// the walk (in parallel). `queue` and `copies` are the caller's lists, kept between calls.
class LineTreeWriter {
 public:
  LineTreeWriter(const CompressedTreeGraph& graph, const AxisBuilder& builder, LineTree& lines,
                 std::vector<LineItem>& queue, std::vector<PlacedCopy>& copies)
      : graph_(graph),
        builder_(builder),
        lines_(lines),
        queue_(queue),
        copies_(copies),
        dependent_(orientation_dependent_below(graph, builder)),
        canonical_(builder.trunk_frame()),
        canonical_inverse_(canonical_.axes.transpose()) {
    protos_.resize_index(graph.size());
    columns_.bind(lines_);
  }

  // Writes the whole plant; returns the number of records written.
  NodeId run(ReconstructionStats& st) {
    queue_.clear();
    copies_.clear();
    walk_frames_.assign(1, builder_.root_frame());
    queue_.push_back(
        {graph_.root(), kNoNode, 0, 0, Eigen::Matrix3f::Identity(), Eigen::Vector3f::Zero()});
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const LineItem item = queue_[head];  // copied: the queue grows below
      if (item.walk_frame != kNoWalk) {
        write_walked_axis(item, st);
      } else {
        place_prototype(item, head, st);
      }
    }
    columns_.bind(lines_);
    copy_placed_prototypes();
    return cursor_;
  }

 private:
  // The bound of size_line_tree holds for every plant the simulation makes; a hand-made graph
  // that breaks it only costs a reallocation.
  void make_room(std::size_t n) {
    if (cursor_ + n <= lines_.size()) return;
    lines_.resize_for_overwrite(std::max<std::size_t>(2 * lines_.size(), cursor_ + n));
    columns_.bind(lines_);
  }

  ReconstructionStats walk_axis(RecordId record, const Frame& frame, std::uint16_t axis_order) {
    scratch_.clear_keep_capacity();
    if (builder_.any_pruning_period()) scratch_.add_attribute(kDeadAttribute, 0.0);
    laterals_.clear();
    ReconstructionStats axis_stats;
    builder_.walk({record, kNoNode, frame, axis_order}, scratch_, laterals_, axis_stats);
    return axis_stats;
  }

  // An axis walked from its absolute frame, written at the cursor; its laterals queued.
  void write_walked_axis(const LineItem& item, ReconstructionStats& st) {
    const NodeId base = cursor_;
    add_stats(st, walk_axis(item.record, walk_frames_[item.walk_frame], item.order));
    make_room(scratch_.size());
    const bool has_dead = scratch_.has_attribute(kDeadAttribute);
    const LineColumns& c = columns_;
    for (NodeId k = 0; k < scratch_.size(); ++k) {
      const NodeId i = base + k;
      c.parent[i] = k == 0 ? item.parent : base + scratch_.parent(k);
      c.start[i] = scratch_.start(k).cast<float>();
      c.direction[i] = scratch_.direction(k).cast<float>();
      c.length[i] = static_cast<float>(scratch_.length(k));
      c.radius[i] = static_cast<float>(scratch_.radius(k));
      c.birth[i] = static_cast<float>(scratch_.birth_time(k));
      c.age[i] = scratch_.physiological_age(k);
      c.order[i] = scratch_.order(k);
      c.kind[i] = scratch_.kind(k);
      if (c.dead) c.dead[i] = has_dead && scratch_.attribute(kDeadAttribute)[k] != 0.0;
    }
    cursor_ += static_cast<NodeId>(scratch_.size());
    for (const AxisStart& l : laterals_) {
      LineItem next{l.record,
                    base + l.parent,
                    l.order,
                    kNoWalk,
                    Eigen::Matrix3f::Identity(),
                    Eigen::Vector3f::Zero()};
      if (dependent_[l.record] != 0) {
        next.walk_frame = static_cast<std::uint32_t>(walk_frames_.size());
        walk_frames_.push_back(l.frame);
      } else {  // placement of the prototype, whose frame is the canonical one
        next.rotation = (l.frame.axes * canonical_inverse_).cast<float>();
        next.translation = l.frame.position.cast<float>();
      }
      queue_.push_back(next);
    }
  }

  // A prototype (walked the first time it is met) placed by the queue's item `head`: its records
  // reserved at the cursor for the copy, its laterals queued with the composed transforms.
  void place_prototype(const LineItem& item, std::size_t head, ReconstructionStats& st) {
    const NodeId base = cursor_;
    std::uint32_t pi = protos_.index_of(item.record);
    if (pi == kNoPrototype) {
      const ReconstructionStats axis_stats = walk_axis(item.record, canonical_, 0);
      pi = protos_.add(item.record, scratch_, laterals_, canonical_inverse_, axis_stats);
    }
    const LinePrototypes::Prototype& p = protos_.prototypes[pi];
    add_stats(st, p.stats);
    make_room(p.count);
    copies_.push_back({pi, base, static_cast<std::uint32_t>(head)});
    cursor_ += p.count;
    const Eigen::Matrix3f& rot = item.rotation;
    const Eigen::Vector3f& shift = item.translation;
    const auto child_order = static_cast<std::uint16_t>(item.order + 1);
    for (std::uint32_t c = 0; c < p.child_count; ++c) {
      const LinePrototypes::Child& child = protos_.children[p.child_first + c];
      queue_.push_back({child.record, base + child.attach, child_order, kNoWalk,
                        rot * child.rotation, rot * child.translation + shift});
    }
  }

  void copy_placed(const PlacedCopy& copy) const {
    const LineItem& item = queue_[copy.item];
    const LinePrototypes::Prototype& p = protos_.prototypes[copy.prototype];
    const LineColumns& c = columns_;
    // One pass per record: prototypes are short (about ten records), so separate copies per
    // column would spend more on starting loops than on copying.
    for (std::uint32_t k = 0; k < p.count; ++k) {
      const std::uint32_t from = p.first + k;
      const NodeId i = copy.base + k;
      c.parent[i] = k == 0 ? item.parent : copy.base + protos_.parent[from];
      c.start[i] = item.rotation * protos_.start[from] + item.translation;
      c.direction[i] = item.rotation * protos_.direction[from];
      c.length[i] = protos_.length[from];
      c.radius[i] = protos_.radius[from];
      c.birth[i] = protos_.birth[from];
      c.age[i] = protos_.age[from];
      c.kind[i] = protos_.kind[from];
      c.order[i] = static_cast<std::uint16_t>(protos_.order[from] + item.order);
    }
    if (c.dead) std::copy_n(protos_.dead.data() + p.first, p.count, c.dead + copy.base);
  }

  // Every placed prototype's records into their own range [base, base + count): the ranges do
  // not overlap, so they are written in parallel, the same records on any number of threads.
  // (The caller's thread_local lists are reached through the references held here: a worker
  // naming them would see its own.)
  void copy_placed_prototypes() const {
    // Isolated: while it waits, this thread takes no unrelated task of an enclosing parallel
    // loop, which could run another reconstruction here and reuse the thread_local lists under
    // it.
    tbb::this_task_arena::isolate([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, copies_.size(), 1024),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t c = range.begin(); c != range.end(); ++c) {
                            copy_placed(copies_[c]);
                          }
                        });
    });
  }

  const CompressedTreeGraph& graph_;
  const AxisBuilder& builder_;
  LineTree& lines_;
  std::vector<LineItem>& queue_;
  std::vector<PlacedCopy>& copies_;
  const std::vector<std::uint8_t> dependent_;
  const Frame canonical_;
  const Eigen::Matrix3d canonical_inverse_;
  LinePrototypes protos_;
  LineColumns columns_;
  NodeId cursor_ = 0;
  std::vector<Frame> walk_frames_;
  TreeGraph scratch_;
  std::vector<AxisStart> laterals_;
};

}  // namespace

LineTree reconstruct_lines(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                           ReconstructionStats* stats) {
  LineTree lines;
  reconstruct_lines_into(graph, options, lines, stats);
  return lines;
}

void reconstruct_lines_into(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                            LineTree& lines, ReconstructionStats* stats) {
  if (options.lod.active()) {
    throw ValueError(
        "the line tree reconstruction draws every metamer: use reconstruct() for a "
        "level of detail");
  }
  if (graph.has_geometry()) {
    ReconstructionStats st;
    lines = LineTree::from_tree_graph(reconstruct_geometry(graph, options, st));
    if (stats) *stats = st;
    return;
  }
  const AxisBuilder builder(graph, options, true);
  ReconstructionStats st;
  st.age = builder.age();
  lines.clear();
  lines.set_has_dead(builder.any_pruning_period());
  if (nothing_born(graph, builder)) {
    if (stats) *stats = st;
    return;
  }
  size_line_tree(graph, builder, lines);
  // The axis starts of the whole plant (176 000 for the Table 1 tree) and the prototypes placed
  // are kept per thread between calls: growth animation frames then neither allocate nor fault
  // them in again.
  thread_local std::vector<LineItem> queue;
  thread_local std::vector<PlacedCopy> copies;
  const NodeId cursor = LineTreeWriter(graph, builder, lines, queue, copies).run(st);
  lines.resize_for_overwrite(cursor);
  if (stats) *stats = st;
}

}  // namespace fspm::greenlab
