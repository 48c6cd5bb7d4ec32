#include "scan_decoding/species_library.hpp"

#include <algorithm>
#include <string>

#include "fspm/error.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/turtle.hpp"
#include "scans/species.hpp"

namespace fspm::scan_decoding {
namespace {

// The habit of a species' shoots, filled into one grammar.
// The first internode of every branchlet (the axiom's A(0.5, ...)), m; later ones are shorter.
constexpr double kFirstInternodeM = 0.5;

struct BranchletShape {
  double angle_deg = 35.0;       // lateral branching angle
  double leaf_length = 0.18;     // leaf blade length, m (the first internode is 0.5 m)
  double leaf_angle_deg = 55.0;  // leaf insertion angle
  double droop_deg = 0.0;        // extra downward pitch of laterals
  double elasticity = 0.0;       // tropism toward -z (ABOP 2.2)
};

BranchletShape shape_for(std::string_view species) {
  BranchletShape s;
  if (species == "pine") {
    s.angle_deg = 70.0, s.leaf_length = 0.09, s.leaf_angle_deg = 40.0;
  } else if (species == "willow") {
    s.angle_deg = 30.0, s.leaf_length = 0.22, s.leaf_angle_deg = 25.0, s.droop_deg = 20.0;
    s.elasticity = 0.25;
  } else if (species == "palm") {
    s.angle_deg = 55.0, s.leaf_length = 0.35, s.leaf_angle_deg = 80.0, s.elasticity = 0.1;
  } else if (species == "delonix" || species == "ficus-virens") {
    s.angle_deg = 50.0, s.leaf_length = 0.14;
  }
  return s;
}

std::string number(double x) { return std::to_string(x); }

}  // namespace

SpeciesSizes species_sizes(std::string_view species) {
  (void)scans::species_by_name(species);  // ValueError naming the presets
  return {shape_for(species).leaf_length, kFirstInternodeM};
}

std::string branchlet_lsystem(std::string_view species) {
  (void)scans::species_by_name(species);  // ValueError naming the presets
  const BranchletShape s = shape_for(species);
  const std::string leaf = "~l(" + number(s.leaf_length) + ")";
  const std::string leaves = "[&(" + number(s.leaf_angle_deg) + ")" + leaf + "][^(" +
                             number(s.leaf_angle_deg) + ")" + leaf + "]";
  const std::string lateral = "[+(" + number(s.angle_deg) + ")&(" + number(s.droop_deg) + ")";
  // A: the branchlet's main axis, B: its laterals; each internode carries two leaves and turns by
  // the golden angle, laterals appear with the given probabilities (ABOP 1.7).
  return "Lsystem: 1\n"
         "Axiom: A(" +
         number(kFirstInternodeM) +
         ",0.05)\n"
         "A(l,w) --> !(w)F(l)" +
         leaves + "/(137.5)" + lateral +
         "B(l*0.8,w*0.6)]A(l*0.9,w*0.85) : 0.8\n"
         "A(l,w) --> !(w)F(l)" +
         leaves +
         "/(137.5)A(l*0.9,w*0.85) : 0.35\n"
         "B(l,w) --> !(w)F(l)" +
         leaves + "/(137.5)" + lateral +
         "B(l*0.75,w*0.6)]B(l*0.85,w*0.8) : 0.6\n"
         "B(l,w) --> !(w)F(l)" +
         leaves +
         "/(137.5)B(l*0.85,w*0.8) : 0.55\n"
         "endlsystem\n";
}

void LibraryOptions::validate() const {
  if (branchlets < 1 || branchlets > 1000) {
    throw ValueError("species library: branchlets (per species) must be within [1, 1000], not " +
                     std::to_string(branchlets));
  }
  if (steps < 1 || steps > 12) {
    throw ValueError(
        "species library: steps (of each branchlet's derivation) must be within "
        "[1, 12], not " +
        std::to_string(steps));
  }
}

SpeciesLibrary make_species_library(std::string_view species, const LibraryOptions& options) {
  options.validate();
  const lsystem::LSystem system =
      lsystem::parse_lsystem(branchlet_lsystem(species), std::string(species) + " branchlets");
  lsystem::TurtleSettings view;
  view.line_width_unit = lsystem::LineWidthUnit::kModel;
  view.initial_line_width = 0.1;
  view.initial_elasticity = shape_for(species).elasticity;
  SpeciesLibrary library;
  library.species = std::string(species);
  for (int k = 0; k < options.branchlets; ++k) {
    lsystem::DeriveOptions derive;
    derive.steps = options.steps;
    derive.seed = options.seed + static_cast<std::uint64_t>(k);
    lsystem::Derivation d(system, derive);
    d.run();
    const lsystem::Interpretation drawn =
        lsystem::interpret(d.interpretation_string(), system.symbols, view);
    std::vector<Patch> patches = cut_into_patches(drawn.tree, static_cast<std::uint32_t>(k));
    for (Patch& p : patches) library.patches.push_back(std::move(p));
  }
  return library;
}

namespace {

bool is_internode(const TreeGraph& t, NodeId n) { return t.kind(n) == OrganKind::kInternode; }

// An axis continues through the first internode child of the same branching order.
NodeId continuation(const TreeGraph& t, NodeId n) {
  for (NodeId c : t.children(n)) {
    if (is_internode(t, c) && t.order(c) == t.order(n)) return c;
  }
  return kNoNode;
}

std::vector<NodeId> axis_from(const TreeGraph& t, NodeId base) {
  std::vector<NodeId> axis{base};
  for (NodeId c = continuation(t, base); c != kNoNode; c = continuation(t, c)) axis.push_back(c);
  return axis;
}

NodeData moved(const TreeGraph& t, NodeId n, const Eigen::Vector3d& origin) {
  NodeData d;
  d.start = t.start(n) - origin;
  d.end = t.end(n) - origin;
  d.direction = t.direction(n);
  d.length = t.length(n);
  d.radius = t.radius(n);
  d.kind = t.kind(n);
  d.order = t.kind(n) == OrganKind::kLeaf ? 1 : 0;
  return d;
}

Patch patch_of_axis(const TreeGraph& t, const std::vector<NodeId>& axis, double base_radius) {
  Patch p;
  const Eigen::Vector3d origin = t.start(axis.front());
  p.direction = t.direction(axis.front()).normalized();
  p.thickness = t.radius(axis.front()) / base_radius;
  NodeId previous = kNoNode;
  for (NodeId a : axis) {
    const NodeId local = p.geometry.add_node(previous, moved(t, a, origin));
    for (NodeId c : t.children(a)) {
      if (!is_internode(t, c)) {
        if (t.kind(c) == OrganKind::kLeaf) ++p.leaves;
        p.geometry.add_node(local, moved(t, c, origin));
      } else if (c != continuation(t, a)) {
        p.dockings.push_back(
            {local, t.start(c) - origin, t.direction(c).normalized(), t.radius(c) / base_radius});
      }
    }
    previous = local;
  }
  for (NodeId n = 0; n < p.geometry.size(); ++n) {
    p.length_m = std::max(p.length_m, p.geometry.end(n).dot(p.direction));
    if (is_internode(p.geometry, n)) p.internode_length_m += p.geometry.length(n);
  }
  return p;
}

}  // namespace

std::vector<Patch> cut_into_patches(const TreeGraph& branchlet, std::uint32_t branchlet_index) {
  if (branchlet.empty() || !is_internode(branchlet, 0) || !(branchlet.radius(0) > 0.0)) {
    throw ValueError("a branchlet must start with an internode of positive radius");
  }
  const double base_radius = branchlet.radius(0);
  std::vector<Patch> patches;
  for (NodeId n = 0; n < branchlet.size(); ++n) {
    if (!is_internode(branchlet, n)) continue;
    const NodeId parent = branchlet.parent(n);
    const bool starts_axis = parent == kNoNode || continuation(branchlet, parent) != n;
    if (!starts_axis) continue;
    patches.push_back(patch_of_axis(branchlet, axis_from(branchlet, n), base_radius));
    patches.back().branchlet = branchlet_index;
  }
  return patches;
}

}  // namespace fspm::scan_decoding
