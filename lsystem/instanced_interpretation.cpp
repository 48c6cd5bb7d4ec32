#include "lsystem/instanced_interpretation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/saturating.hpp"
#include "lsystem/turtle_core.hpp"
#include "lsystem/turtle_graph_builder.hpp"

namespace fspm::lsystem {
namespace {

constexpr std::uint32_t kNoPrototype = std::numeric_limits<std::uint32_t>::max();

using Turtle = detail::Turtle<detail::GraphBuilder>;

// The turtle's orientation as the rotation that takes the start frame (H = z, L = -x, U = -y)
// to it: columns -L, -U, H.
Eigen::Matrix3d rotation_of(const detail::Frame& f) {
  Eigen::Matrix3d r;
  r.col(0) = -f.left;
  r.col(1) = -f.up;
  r.col(2) = f.heading;
  return r;
}

// Bracket and brace balance of a module sequence: net change and lowest running depth.
struct Balance {
  double bracket_net = 0.0, bracket_low = 0.0, brace_net = 0.0, brace_low = 0.0;

  void then(const Balance& b) {
    bracket_low = std::min(bracket_low, bracket_net + b.bracket_low);
    brace_low = std::min(brace_low, brace_net + b.brace_low);
    bracket_net += b.bracket_net;
    brace_net += b.brace_net;
  }
  bool self_contained() const {
    return bracket_net == 0.0 && bracket_low >= 0.0 && brace_net == 0.0 && brace_low >= 0.0;
  }
};

// What drawing a substructure from one entry state gives, in the frame where it starts.
struct Drawn {
  std::uint32_t prototype = kNoPrototype;                  // none when it draws nothing
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // the turtle where it ends
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double width = 0.0;
  int color = 0;
  Eigen::AlignedBox3d box;  // everything drawn (an upper bound through rotated child boxes)
};

// A substructure drawn from an entry line width and colour.
struct Key {
  std::uint32_t node = 0;
  std::uint64_t width_bits = 0;
  int color = 0;
  bool operator==(const Key&) const = default;
};

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::uint64_t h = k.node;
    h = h * 0x9E3779B97F4A7C15ull ^ k.width_bits;
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.color);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

// One prototype being drawn: its turtle, what it has drawn so far, and where it is in the graph
// (a stack of child lists: the substructure's own, then those of the ones walked through).
struct Build {
  Build(const TurtleSettings& settings, Key k, bool is_root)
      : key(k), root(is_root), builder(out), turtle(settings, builder) {
    turtle.f.width = std::bit_cast<double>(k.width_bits);
    turtle.f.color = k.color;
  }
  struct Walk {
    const std::uint32_t* items;
    std::uint32_t count;
    std::uint32_t next;
  };
  Key key;
  bool root;
  Interpretation out;
  detail::GraphBuilder builder;
  Turtle turtle;
  std::vector<InstancedTree::Child> children;
  Eigen::AlignedBox3d child_box;
  std::vector<Walk> walk;
};

// The box of `box` rotated and moved (its corners' box: an upper bound).
Eigen::AlignedBox3d transformed(const Eigen::AlignedBox3d& box, const Eigen::Matrix3d& r,
                                const Eigen::Vector3d& t) {
  Eigen::AlignedBox3d out;
  if (box.isEmpty()) return out;
  for (int c = 0; c < 8; ++c) {
    out.extend(r * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c)) + t);
  }
  return out;
}

// Every point the explicit interpretation's extent looks at: node ends and polygon vertices.
std::vector<Eigen::Vector3d> drawn_points(const Interpretation& in) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(2 * in.tree.size());
  for (NodeId n = 0; n < in.tree.size(); ++n) {
    points.push_back(in.tree.start(n));
    points.push_back(in.tree.end(n));
  }
  for (const LeafPolygon& leaf : in.leaves) {
    points.insert(points.end(), leaf.vertices.begin(), leaf.vertices.end());
  }
  return points;
}

class Interpreter {
 public:
  Interpreter(const SubstructureGraph& graph, const LSystem& system, const TurtleSettings& settings,
              const InstancedInterpretationOptions& options)
      : graph_(graph),
        system_(system),
        settings_(settings),
        options_(options),
        actions_(detail::action_table(system.symbols)) {}

  InstancedInterpretation run() {
    if (auto why = homomorphism_obstacle(system_)) {
      return run_explicit("it has " + *why);
    }
    prepare_leaves();
    if (auto why = absolute_orientation()) return run_explicit(*why);
    draw_all();
    put_root_first();
    InstancedInterpretation result;
    result.tree.prototypes = std::move(prototypes_);
    result.bounds = root_box_;
    count(result);
    if (settings_.line_width_unit == LineWidthUnit::kPixel) scale_pixel_widths(result);
    return result;
  }

 private:
  // The interpretation string of every leaf (its homomorphism) and the balance of every node.
  void prepare_leaves() {
    const std::size_t n = graph_.nodes.size();
    leaf_strings_.resize(n);
    balance_.resize(n);
    std::optional<Derivation> derivation;
    if (!system_.homomorphism.productions.empty()) derivation.emplace(system_);
    for (std::size_t i = 0; i < n; ++i) {
      const Substructure& s = graph_.nodes[i];
      Balance& b = balance_[i];
      if (!s.leaf()) {
        for (std::uint32_t c = 0; c < s.child_count; ++c) {
          b.then(balance_[graph_.children[s.child_begin + c]]);
        }
        continue;
      }
      const std::span<const double> p(graph_.parameters.data() + s.parameter_begin,
                                      s.parameter_count);
      ModuleString& m = leaf_strings_[i];
      if (derivation) {
        derivation->interpret_module(s.symbol, p, m);
      } else {
        m.push_back(s.symbol, p);
      }
      for (std::size_t k = 0; k < m.size(); ++k) b.then(module_balance(actions_[m.symbol(k)]));
    }
  }

  static Balance module_balance(detail::Action a) {
    Balance b;
    const double bracket = a == detail::Action::kPush ? 1.0 : a == detail::Action::kPop ? -1.0 : 0;
    const double brace = a == detail::Action::kPolygonBegin ? 1.0
                         : a == detail::Action::kPolygonEnd ? -1.0
                                                            : 0.0;
    b.bracket_net = bracket;
    b.bracket_low = std::min(0.0, bracket);
    b.brace_net = brace;
    b.brace_low = std::min(0.0, brace);
    return b;
  }

  // Why drawing depends on the absolute orientation, or nothing.
  std::optional<std::string> absolute_orientation() const {
    const bool tropism =
        settings_.tropism_direction.squaredNorm() > 0.0 &&
        (settings_.initial_elasticity != 0.0 || settings_.elasticity_increment != 0.0);
    if (tropism) {
      return std::string("tropism, which bends every internode toward an absolute direction");
    }
    for (const ModuleString& m : leaf_strings_) {
      for (const SymbolId s : m.symbols()) {
        if (actions_[s] == detail::Action::kRollHorizontal) {
          return std::string("$, which rolls the turtle until its left side is horizontal");
        }
      }
    }
    return std::nullopt;
  }

  InstancedInterpretation run_explicit(const std::string& reason) {
    InstancedInterpretation result;
    result.explicit_reason = reason;
    Derivation d(system_);
    d.string() = expand(graph_, options_.module_budget);
    Interpretation drawn = interpret(d.interpretation_string(), system_.symbols, settings_);
    for (NodeId n = 0; n < drawn.tree.size(); ++n) {
      const OrganKind k = drawn.tree.kind(n);
      result.internodes += k == OrganKind::kInternode ? 1 : 0;
      result.leaves += k == OrganKind::kLeaf ? 1 : 0;
      result.flowers += k == OrganKind::kFlower ? 1 : 0;
    }
    result.instances = drawn.tree.empty() ? 0 : 1;
    result.occurrences = 1;
    for (const auto& p : drawn_points(drawn)) result.bounds.extend(p);
    result.tree.prototypes.push_back({std::move(drawn.tree), {}});
    return result;
  }

  // Depth first over prototypes: a substructure met for the first time with an entry state is
  // drawn (pushed) before the one containing it goes on.
  void draw_all() {
    const Key root_key{0, std::bit_cast<std::uint64_t>(settings_.initial_line_width), 0};
    builds_.push_back(std::make_unique<Build>(settings_, root_key, true));
    builds_.back()->walk.push_back(
        {graph_.axiom.data(), static_cast<std::uint32_t>(graph_.axiom.size()), 0});
    for (;;) {
      Build& b = *builds_.back();
      if (b.walk.empty()) {
        const Drawn d = finish(b);
        builds_.pop_back();
        if (builds_.empty()) return;
        place(*builds_.back(), d);
        continue;
      }
      Build::Walk& w = b.walk.back();
      if (w.next == w.count) {
        b.walk.pop_back();
        continue;
      }
      visit(b, w.items[w.next++]);
    }
  }

  // One substructure of the walk of `b`: drawn module by module (a leaf), walked through (not
  // self-contained, or inside a polygon), placed (known), or pushed to be drawn.
  void visit(Build& b, std::uint32_t id) {
    const Substructure& s = graph_.nodes[id];
    if (s.leaf()) {
      const ModuleString& m = leaf_strings_[id];
      for (std::size_t k = 0; k < m.size(); ++k) {
        const detail::Action a = actions_[m.symbol(k)];
        if (a != detail::Action::kNone) b.turtle.apply(a, m.parameters(k), 0);
      }
      return;
    }
    if (!balance_[id].self_contained() || b.turtle.polygon_depth > 0) {
      b.walk.push_back({graph_.children.data() + s.child_begin, s.child_count, 0});
      return;
    }
    const Key key{id, std::bit_cast<std::uint64_t>(b.turtle.f.width), b.turtle.f.color};
    if (const auto it = memo_.find(key); it != memo_.end()) {
      place(b, drawn_[it->second]);
      return;
    }
    builds_.push_back(std::make_unique<Build>(settings_, key, false));
    builds_.back()->walk.push_back({graph_.children.data() + s.child_begin, s.child_count, 0});
  }

  // The substructure of `b` is drawn: its prototype (unless it draws nothing) and exit state.
  Drawn finish(Build& b) {
    b.builder.store_attributes();
    const detail::Frame& f = b.turtle.f;
    Drawn d;
    d.rotation = rotation_of(f);
    d.position = f.position;
    d.width = f.width;
    d.color = f.color;
    d.box = b.child_box;
    std::vector<Eigen::Vector3d> points = drawn_points(b.out);
    for (const auto& p : points) d.box.extend(p);
    if (b.root || !b.out.tree.empty() || !b.children.empty()) {
      d.prototype = static_cast<std::uint32_t>(prototypes_.size());
      prototypes_.push_back({std::move(b.out.tree), std::move(b.children)});
      line_width_nodes_.push_back(std::move(b.builder.line_width_nodes_));
      points_.push_back(std::move(points));
    }
    if (b.root) root_box_ = d.box;
    if (!b.root) {
      memo_.emplace(b.key, static_cast<std::uint32_t>(drawn_.size()));
      drawn_.push_back(d);
    }
    return d;
  }

  // An occurrence of a drawn substructure where the turtle of `b` stands, then the turtle moved
  // to where it leaves it.
  void place(Build& b, const Drawn& d) {
    detail::Frame& f = b.turtle.f;
    const Eigen::Matrix3d r = rotation_of(f);
    if (d.prototype != kNoPrototype) {
      if (options_.min_detail > 0.0 && d.box.diagonal().norm() < options_.min_detail) {
        draw_chord(b, r * d.position + f.position);
      } else {
        b.children.push_back({d.prototype, f.node, r, f.position, static_cast<double>(f.depth)});
        b.child_box.extend(transformed(d.box, r, f.position));
      }
    }
    f.position += r * d.position;
    const Eigen::Matrix3d exit = r * d.rotation;
    f.left = -exit.col(0);
    f.up = -exit.col(1);
    f.heading = exit.col(2);
    f.width = d.width;
    f.color = d.color;
  }

  // Level of detail: one internode from the turtle to `end`, in the turtle's width and colour.
  void draw_chord(Build& b, const Eigen::Vector3d& end) {
    detail::Frame& f = b.turtle.f;
    const Eigen::Vector3d v = end - f.position;
    const double length = v.norm();
    if (length == 0.0) return;
    detail::Frame at_end = f;
    at_end.position = end;
    b.builder.forward(f.position, v / length, length, at_end);
    f.node = at_end.node;
  }

  // Prototypes were stored as they were finished (children first, the root last): reversed, the
  // root comes first and every parent before its children.
  void put_root_first() {
    std::reverse(prototypes_.begin(), prototypes_.end());
    std::reverse(line_width_nodes_.begin(), line_width_nodes_.end());
    std::reverse(points_.begin(), points_.end());
    const auto last = static_cast<std::uint32_t>(prototypes_.size() - 1);
    for (auto& p : prototypes_) {
      for (auto& c : p.children) c.prototype = last - c.prototype;
    }
    occurrences_.assign(prototypes_.size(), 0);
    occurrences_[0] = 1;
    for (std::size_t p = 0; p < prototypes_.size(); ++p) {
      for (const auto& c : prototypes_[p].children) {
        occurrences_[c.prototype] = add_saturating(occurrences_[c.prototype], occurrences_[p]);
      }
    }
  }

  void count(InstancedInterpretation& result) const {
    for (std::size_t p = 0; p < result.tree.prototypes.size(); ++p) {
      const TreeGraph& g = result.tree.prototypes[p].geometry;
      std::uint64_t internodes = 0, leaves = 0, flowers = 0;
      for (const OrganKind k : g.kinds()) {
        internodes += k == OrganKind::kInternode ? 1 : 0;
        leaves += k == OrganKind::kLeaf ? 1 : 0;
        flowers += k == OrganKind::kFlower ? 1 : 0;
      }
      const std::uint64_t times = occurrences_[p];
      result.internodes = add_saturating(result.internodes, multiply_saturating(times, internodes));
      result.leaves = add_saturating(result.leaves, multiply_saturating(times, leaves));
      result.flowers = add_saturating(result.flowers, multiply_saturating(times, flowers));
      if (!g.empty()) result.instances = add_saturating(result.instances, times);
      result.occurrences = add_saturating(result.occurrences, times);
    }
  }

  // The plant's largest extent: exact over every drawn point when there are few enough, else
  // from the root's box.
  double largest_extent(const InstancedTree& tree) const {
    double points = 0.0;
    for (std::size_t p = 0; p < points_.size(); ++p) {
      points += static_cast<double>(occurrences_[p]) * static_cast<double>(points_[p].size());
    }
    Eigen::AlignedBox3d box;
    if (points > kExactExtentPoints) {
      box = root_box_;
    } else {
      struct Item {
        std::uint32_t prototype;
        Eigen::Matrix3d rotation;
        Eigen::Vector3d translation;
      };
      std::vector<Item> stack{{0, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()}};
      while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        for (const auto& p : points_[item.prototype]) {
          box.extend(item.rotation * p + item.translation);
        }
        for (const auto& c : tree.prototypes[item.prototype].children) {
          stack.push_back({c.prototype, item.rotation * c.rotation,
                           item.rotation * c.translation + item.translation});
        }
      }
    }
    return box.isEmpty() ? 0.0 : box.sizes().maxCoeff();
  }

  // Pixel widths: the plant spans kPixelsAcrossPlant pixels of the picture they were drawn in.
  void scale_pixel_widths(InstancedInterpretation& result) const {
    const double units_per_pixel = largest_extent(result.tree) / kPixelsAcrossPlant;
    for (std::size_t p = 0; p < result.tree.prototypes.size(); ++p) {
      TreeGraph& g = result.tree.prototypes[p].geometry;
      for (const NodeId n : line_width_nodes_[p]) g.set_radius(n, g.radius(n) * units_per_pixel);
    }
  }

  const SubstructureGraph& graph_;
  const LSystem& system_;
  const TurtleSettings& settings_;
  const InstancedInterpretationOptions& options_;
  const std::vector<detail::Action> actions_;
  std::vector<ModuleString> leaf_strings_;  // per leaf node: its interpretation modules
  std::vector<Balance> balance_;            // per node
  std::vector<std::unique_ptr<Build>> builds_;
  std::unordered_map<Key, std::uint32_t, KeyHash> memo_;  // -> drawn_
  std::vector<Drawn> drawn_;
  std::vector<InstancedTree::Prototype> prototypes_;
  std::vector<std::vector<NodeId>> line_width_nodes_;  // per prototype
  std::vector<std::vector<Eigen::Vector3d>> points_;   // per prototype: its drawn points
  std::vector<std::uint64_t> occurrences_;             // per prototype
  Eigen::AlignedBox3d root_box_;
};

}  // namespace

InstancedInterpretation interpret_instanced(const SubstructureGraph& graph, const LSystem& system,
                                            const TurtleSettings& settings,
                                            const InstancedInterpretationOptions& options) {
  return Interpreter(graph, system, settings, options).run();
}

}  // namespace fspm::lsystem
