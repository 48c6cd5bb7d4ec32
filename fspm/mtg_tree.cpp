#include "fspm/mtg_tree.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <map>
#include <mutex>
#include <set>

#include "fspm/error.hpp"
#include "fspm/plant_frame.hpp"
#include "fspm/warning.hpp"

namespace fspm {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Beyond these, a plant read in metres was most likely measured in centimetres or millimetres.
constexpr double kImplausibleHeightM = 200.0;
constexpr double kImplausibleRadiusM = 10.0;

std::mutex& defaults_mutex() {
  static std::mutex m;
  return m;
}
MtgTreeOptions& defaults() {
  static MtgTreeOptions o;
  return o;
}

// The features that carry geometry, by the names OpenAlea's PlantFrame and common data sets use.
struct Roles {
  std::optional<std::size_t> x, y, z, length, diameter, radius, insertion, azimuth, birth, order,
      organ;
};

std::optional<std::size_t> find(const Mtg& mtg, std::initializer_list<const char*> names) {
  for (const char* n : names) {
    if (auto f = mtg.feature_index(n)) return f;
  }
  return std::nullopt;
}

Roles feature_roles(const Mtg& mtg) {
  Roles r;
  r.x = find(mtg, {"XX"});
  r.y = find(mtg, {"YY"});
  r.z = find(mtg, {"ZZ"});
  r.length = find(mtg, {"Length", "length", "Long", "longueur", "len"});
  r.diameter = find(mtg, {"TopDia", "TopDiameter", "Diameter", "diameter", "diam", "diasom",
                          "BotDia", "BottomDiameter", "BottomDia", "diabase"});
  r.radius = find(mtg, {"Radius", "radius"});
  r.insertion = find(mtg, {"Alpha", "insertion", "AngBas"});
  r.azimuth = find(mtg, {"Azimuth", "azimuth"});
  r.birth = find(mtg, {"BirthTime"});
  r.order = find(mtg, {"Order"});
  r.organ = find(mtg, {"Organ"});
  return r;
}

// A length for a message, in whole metres ("1e+300" beyond what a long holds).
std::string metres_text(double m) {
  char text[32];
  std::snprintf(text, sizeof(text), std::abs(m) < 1e15 ? "%.0f" : "%.3g", m);
  return text;
}

bool has_geometry(const Mtg& mtg, const Roles& r, MtgVertex v) {
  for (const auto& f : {r.x, r.length, r.diameter, r.radius}) {
    if (f && !mtg.feature_text(v, *f).empty()) return true;
  }
  return false;
}

int choose_scale(const Mtg& mtg, const Roles& r, int requested, const std::string& file) {
  if (mtg.max_scale() == 0) {
    throw ValueError("the MTG holds no entity (its code has no line after the header)", file);
  }
  if (requested >= 0) {
    if (requested < 1 || requested > mtg.max_scale()) {
      throw ValueError("--mtg-scale " + std::to_string(requested) +
                           ": expected a scale from 1 to " + std::to_string(mtg.max_scale()),
                       file);
    }
    return requested;
  }
  for (int s = mtg.max_scale(); s >= 1; --s) {
    for (MtgVertex v = 1; v < mtg.size(); ++v) {
      if (mtg.scale(v) == s && has_geometry(mtg, r, v)) return s;
    }
  }
  return mtg.max_scale();
}

bool plant_matches(const Mtg& mtg, MtgVertex v, const std::string& plant) {
  const MtgVertex p = mtg.plant_of(v);
  return p != kNoMtgVertex &&
         (mtg.label(p) == plant || (mtg.index(p) >= 0 && std::to_string(mtg.index(p)) == plant));
}

// The entities of `scale` in depth-first order from their roots, children in file order.
std::vector<MtgVertex> ordered_entities(const Mtg& mtg, int scale, const std::string& plant) {
  std::vector<MtgVertex> order, stack;
  for (MtgVertex v = 1; v < mtg.size(); ++v) {
    if (mtg.scale(v) != scale || (!plant.empty() && !plant_matches(mtg, v, plant))) continue;
    const MtgVertex p = mtg.parent(v);
    if (p != kNoMtgVertex && (plant.empty() || plant_matches(mtg, p, plant))) continue;
    stack.push_back(v);
    while (!stack.empty()) {
      const MtgVertex u = stack.back();
      stack.pop_back();
      order.push_back(u);
      const auto c = mtg.children(u);
      for (auto it = c.rbegin(); it != c.rend(); ++it) stack.push_back(*it);
    }
  }
  return order;
}

double median(std::vector<double> v, double fallback) {
  if (v.empty()) return fallback;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

class TreeBuilder {
 public:
  TreeBuilder(const Mtg& mtg, const MtgTreeOptions& o, const std::string& file)
      : mtg_(mtg),
        o_(o),
        file_(file),
        roles_(feature_roles(mtg)),
        length_factor_(metres_per_unit(o.length_unit)),
        diameter_factor_(metres_per_unit(o.diameter_unit.value_or(o.length_unit))) {}

  TreeGraph build(MtgTreeReport& report) {
    report.scale = choose_scale(mtg_, roles_, o_.scale, file_);
    order_ = ordered_entities(mtg_, report.scale, o_.plant);
    if (order_.empty()) throw_empty(report.scale);
    position_.assign(mtg_.size(), kNoFrameParent);
    for (std::size_t i = 0; i < order_.size(); ++i) position_[order_[i]] = i;
    const std::vector<FrameEntity> entities = measured_entities();
    std::vector<FramedEntity> frame = plant_frame(entities, frame_defaults(entities));
    report.plants = lay_out_plants(entities, frame);
    TreeGraph tree = make_tree(entities, frame);
    for (const FramedEntity& f : frame) {
      report.positions_inferred += (f.inferred & kInferredPosition) != 0;
      report.radii_inferred += (f.inferred & kInferredRadius) != 0;
    }
    report.entities_left_out = left_out(report.scale);
    warn_of_units(frame);
    return tree;
  }

 private:
  [[noreturn]] void throw_empty(int scale) const {
    if (!o_.plant.empty()) {
      std::string plants;
      for (MtgVertex v = 1; v < mtg_.size() && plants.size() < 80; ++v) {
        if (mtg_.scale(v) == 1) plants += (plants.empty() ? "" : ", ") + mtg_.label(v);
      }
      throw ValueError("--plant " + o_.plant + ": no such plant at scale " + std::to_string(scale) +
                           "; the file's plants are " + plants,
                       file_);
    }
    throw ValueError("the MTG has no entity at scale " + std::to_string(scale), file_);
  }

  std::optional<double> number(MtgVertex v, const std::optional<std::size_t>& f) const {
    if (!f) return std::nullopt;
    return mtg_.feature_number(v, *f);
  }

  // A feature that places or sizes an entity: a finite number ("nan" and "inf" read as numbers
  // would make the whole plant's geometry non-finite), not negative for a size. Refused with
  // the entity's line, since the tree built from it could not be drawn or written.
  std::optional<double> geometry(MtgVertex v, const std::optional<std::size_t>& f,
                                 bool size = false) const {
    const std::optional<double> n = number(v, f);
    if (n && (!std::isfinite(*n) || (size && *n < 0.0))) {
      throw ParseError("feature " + mtg_.features()[*f].name + ": '" +
                           std::string(mtg_.feature_text(v, *f)) + "', expected a " +
                           (size ? "finite number >= 0" : "finite number"),
                       file_, mtg_.line(v));
    }
    return n;
  }

  std::vector<FrameEntity> measured_entities() const {
    std::vector<FrameEntity> out(order_.size());
    for (std::size_t i = 0; i < order_.size(); ++i) {
      const MtgVertex v = order_[i];
      FrameEntity& e = out[i];
      const MtgVertex p = mtg_.parent(v);
      if (p != kNoMtgVertex && position_[p] != kNoFrameParent) e.parent = position_[p];
      e.branch = mtg_.edge(v) == MtgEdge::kBranch;
      const auto x = geometry(v, roles_.x), y = geometry(v, roles_.y), z = geometry(v, roles_.z);
      if (x && y && z) e.top = Eigen::Vector3d(*x, *y, *z) * length_factor_;
      if (const auto l = geometry(v, roles_.length, true)) e.length_m = *l * length_factor_;
      if (const auto r = geometry(v, roles_.radius, true)) {
        e.radius_m = *r * diameter_factor_;
      } else if (const auto d = geometry(v, roles_.diameter, true)) {
        e.radius_m = 0.5 * *d * diameter_factor_;
      }
      e.insertion_deg = geometry(v, roles_.insertion);
      e.azimuth_deg = geometry(v, roles_.azimuth);
    }
    return out;
  }

  // The default length: the median measured length, else the median distance between measured
  // tops of an entity and its parent, else 10 cm.
  FrameDefaults frame_defaults(const std::vector<FrameEntity>& e) const {
    std::vector<double> lengths, spans;
    for (const FrameEntity& f : e) {
      if (f.length_m && *f.length_m > 0.0) lengths.push_back(*f.length_m);
      if (f.top && f.parent != kNoFrameParent && e[f.parent].top) {
        const double d = (*f.top - *e[f.parent].top).norm();
        if (d > 0.0) spans.push_back(d);
      }
    }
    FrameDefaults d;
    d.length_m = lengths.empty() ? median(spans, 0.1) : median(lengths, 0.1);
    return d;
  }

  // Plants without any measured position stand side by side along x, 1 m apart.
  std::size_t lay_out_plants(const std::vector<FrameEntity>& e, std::vector<FramedEntity>& f) {
    root_of_.assign(e.size(), 0);
    std::vector<std::size_t> roots;
    bool measured = false;
    for (std::size_t i = 0; i < e.size(); ++i) {
      root_of_[i] = e[i].parent == kNoFrameParent ? i : root_of_[e[i].parent];
      if (e[i].parent == kNoFrameParent) roots.push_back(i);
      measured = measured || e[i].top.has_value();
    }
    if (roots.size() < 2 || measured) return roots.size();
    std::map<std::size_t, std::pair<double, double>> extent;  // root: min x, max x
    for (std::size_t i = 0; i < f.size(); ++i) {
      auto [it, added] = extent.try_emplace(root_of_[i], f[i].end.x(), f[i].end.x());
      for (double x : {f[i].start.x(), f[i].end.x()}) {
        it->second.first = std::min(it->second.first, x);
        it->second.second = std::max(it->second.second, x);
      }
    }
    std::map<std::size_t, double> shift;
    double next = 0.0;
    for (std::size_t r : roots) {
      shift[r] = next - extent[r].first;
      next += extent[r].second - extent[r].first + 1.0;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      f[i].start.x() += shift[root_of_[i]];
      f[i].end.x() += shift[root_of_[i]];
    }
    return roots.size();
  }

  TreeGraph make_tree(const std::vector<FrameEntity>& e, const std::vector<FramedEntity>& f);
  void add_attributes(TreeGraph& tree, NodeId offset);
  std::size_t left_out(int scale) const;
  void warn_of_units(const std::vector<FramedEntity>& f) const;

  const Mtg& mtg_;
  const MtgTreeOptions& o_;
  const std::string& file_;
  Roles roles_;
  double length_factor_, diameter_factor_;
  std::vector<MtgVertex> order_;
  std::vector<std::size_t> position_, root_of_;
};

OrganKind organ_kind(std::string_view text) {
  for (OrganKind k : {OrganKind::kLeaf, OrganKind::kFlower, OrganKind::kBud}) {
    if (organ_kind_name(k) == text) return k;
  }
  return OrganKind::kInternode;
}

TreeGraph TreeBuilder::make_tree(const std::vector<FrameEntity>& e,
                                 const std::vector<FramedEntity>& f) {
  TreeGraph tree;
  tree.reserve(e.size() + 1);
  std::size_t roots = 0;
  for (const FrameEntity& x : e) roots += x.parent == kNoFrameParent;
  // Several plants: the scale-0 entity, a point at the origin, bears them all.
  const NodeId offset = roots > 1 ? 1 : 0;
  if (offset) tree.add_node(kNoNode, NodeData{});
  for (std::size_t i = 0; i < e.size(); ++i) {
    const MtgVertex v = order_[i];
    NodeData d;
    d.start = f[i].start;
    d.end = f[i].end;
    if (e[i].length_m && *e[i].length_m == 0.0 && e[i].top) d.start = d.end;  // a point organ
    if (e[i].length_m) {
      // The measured length is kept even where it is not the segment's (a curved shoot).
      d.length = *e[i].length_m;
      const Eigen::Vector3d segment = d.end - d.start;
      if (segment.norm() > 0.0) d.direction = segment.normalized();
    }
    d.radius = f[i].radius_m;
    const NodeId parent = e[i].parent == kNoFrameParent ? (offset ? 0 : kNoNode)
                                                        : static_cast<NodeId>(e[i].parent) + offset;
    if (e[i].parent != kNoFrameParent) {
      d.order = static_cast<std::uint16_t>(tree.order(parent) + (e[i].branch ? 1 : 0));
    }
    if (const auto o = number(v, roles_.order); o && *o >= 0 && *o <= 65535) {
      d.order = static_cast<std::uint16_t>(*o);
    }
    if (const auto b = geometry(v, roles_.birth)) d.birth_time = *b;
    if (roles_.organ) d.kind = organ_kind(mtg_.feature_text(v, *roles_.organ));
    tree.add_node(parent, d);
  }
  add_attributes(tree, offset);
  auto inferred = tree.attribute("inferred");
  for (std::size_t i = 0; i < f.size(); ++i) inferred[i + offset] = f[i].inferred;
  return tree;
}

void TreeBuilder::add_attributes(TreeGraph& tree, NodeId offset) {
  tree.add_attribute("class", kNaN);
  tree.add_attribute("index", kNaN);
  tree.add_attribute("inferred", 0.0);
  auto cls = tree.attribute("class");
  auto idx = tree.attribute("index");
  for (std::size_t i = 0; i < order_.size(); ++i) {
    const MtgVertex v = order_[i];
    cls[i + offset] = static_cast<double>(mtg_.class_id(v));
    if (mtg_.index(v) >= 0) idx[i + offset] = static_cast<double>(mtg_.index(v));
    for (MtgVertex c = mtg_.complex(v); c != kNoMtgVertex && c != Mtg::root();
         c = mtg_.complex(c)) {
      const std::string name = mtg_.symbol(c) + "_index";
      if (!tree.has_attribute(name)) tree.add_attribute(name, kNaN);
      if (mtg_.index(c) >= 0) tree.attribute(name)[i + offset] = static_cast<double>(mtg_.index(c));
    }
  }
  const std::set<std::optional<std::size_t>> used{roles_.x,      roles_.y,      roles_.z,
                                                  roles_.length, roles_.radius, roles_.birth,
                                                  roles_.order,  roles_.organ,  roles_.diameter};
  for (std::size_t f = 0; f < mtg_.features().size(); ++f) {
    std::string name = mtg_.features()[f].name;
    if (used.count(f) || name.empty()) continue;
    if (tree.has_attribute(name)) name = "mtg_" + name;
    if (tree.has_attribute(name)) continue;
    tree.add_attribute(name, kNaN);
    auto column = tree.attribute(name);
    const bool text = !mtg_feature_is_number(mtg_.features()[f].type) &&
                      !mtg_feature_is_date(mtg_.features()[f].type);
    std::map<std::string_view, double> rank;
    for (std::size_t i = 0; i < order_.size(); ++i) {
      const std::string_view t = mtg_.feature_text(order_[i], f);
      if (t.empty()) continue;
      if (text) {
        column[i + offset] =
            rank.try_emplace(t, static_cast<double>(rank.size() + 1)).first->second;
      } else if (const auto n = mtg_.feature_number(order_[i], f)) {
        column[i + offset] = *n;
      }
    }
  }
}

// Entities of coarser scales that have no component at `scale`: not in the tree.
std::size_t TreeBuilder::left_out(int scale) const {
  std::size_t n = 0;
  for (MtgVertex v = 1; v < mtg_.size(); ++v) {
    if (mtg_.scale(v) < scale && mtg_.components(v).empty()) ++n;
  }
  if (n > 0) {
    warn(file_ + ": " + std::to_string(n) + " entities of scales coarser than " +
         std::to_string(scale) +
         " have no components at that scale and are not in the tree; "
         "--mtg-scale chooses another scale");
  }
  return n;
}

void TreeBuilder::warn_of_units(const std::vector<FramedEntity>& f) const {
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin, rmax = 0.0;
  for (const FramedEntity& x : f) {
    zmin = std::min({zmin, x.start.z(), x.end.z()});
    zmax = std::max({zmax, x.start.z(), x.end.z()});
    if (!(x.inferred & kInferredRadius)) rmax = std::max(rmax, x.radius_m);
  }
  if (o_.length_unit == LengthUnit::kMetre && zmax - zmin > kImplausibleHeightM) {
    warn(file_ + ": the plant is " + metres_text(zmax - zmin) +
         " m tall when its lengths are read in metres; if they are centimetres or millimetres, "
         "give --length-unit cm (or mm)");
  }
  if (o_.diameter_unit.value_or(o_.length_unit) == LengthUnit::kMetre &&
      rmax > kImplausibleRadiusM) {
    warn(file_ + ": a radius of " + metres_text(rmax) +
         " m when diameters are read in metres; if they are millimetres, give --diameter-unit mm");
  }
}

}  // namespace

TreeGraph mtg_to_tree(const Mtg& mtg, const MtgTreeOptions& options, MtgTreeReport* report,
                      const std::string& file) {
  MtgTreeReport local;
  return TreeBuilder(mtg, options, file).build(report ? *report : local);
}

void set_default_mtg_tree_options(const MtgTreeOptions& options) {
  const std::lock_guard<std::mutex> lock(defaults_mutex());
  defaults() = options;
}

MtgTreeOptions default_mtg_tree_options() {
  const std::lock_guard<std::mutex> lock(defaults_mutex());
  return defaults();
}

}  // namespace fspm
